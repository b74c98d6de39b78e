// The scene's fog as the renderer meets it (§5 of the paper): what the fog between the
// camera and a point lets through and adds — the sunlight it scatters in the sunlit
// parts of the view ray only (the light beams: sunlit intervals from shadow volumes,
// each integrated in closed form, Appendix), and the sky light it scatters (Eqs. 13–14)
// — and how it dims the sun and the sky light that reach a surface inside it.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/geometry/sun_shadow_volumes.h"
#include "skylit/media/fog_behind_surface.h"
#include "skylit/media/fog_layer.h"
#include "skylit/media/fog_shadowed_sunlight.h"
#include "skylit/media/fog_sky_light.h"
#include "skylit/media/fog_surface_light.h"
#include "skylit/spectrum/medium_stretch.h"

namespace skylit {

class FogMedium {
 public:
  // `camera` is where the view rays start: the sky light the fog scatters toward it
  // depends only on a ray's elevation and length (the layer is level and the sky light
  // in it depends only on altitude), so it is tabulated once for the camera.
  // `tracer` holds the same meshes (what a surface in a shadow sees of the fog around
  // it); it must outlive this.
  FogMedium(const FogSettings& settings, const std::vector<const TriangleMesh*>& meshes, const RayTracer& tracer,
            const SkyModel& sky, const Vec3& camera);
  // The surface light refers to the sky light held here: not copied, not moved.
  FogMedium(const FogMedium&) = delete;
  FogMedium& operator=(const FogMedium&) = delete;

  // What the fog does along `ray` (unit direction) from its origin to `distance` (may be
  // infinite: the sky), in two parts for the air that shares the layer (view_path.h):
  // `near` from the origin to `seen_distance`, which holds all the fog's light, and
  // beyond it only a transmittance. `seen_distance` is where the ray leaves the layer, or
  // sooner where the fog's optical depth from the ray's entry reaches kSeenDepth in
  // every bin: the fog hides whatever lies farther to e^−10, and the air mixed with it
  // there changes nothing visible. [entry_distance, seen_distance] is empty when the
  // ray misses the layer.
  struct Along {
    MediumStretch near;
    Transmittance beyond{1.0f};
    double entry_distance = 0, seen_distance = 0;
    // With multiple scattering, for a ray that ends on a surface: δ-M's forward spike.
    // `near.in_scattered` holds the spike of the open layer's diffuse radiance D (f·D in
    // the source); the light a unit of scattering sends straight on is the surface's own
    // where the ray ends on one. Exactly, the camera then sees (L − D(end))·forward_gain
    // more of a surface leaving L, forward_gain = e^(−(1 − ωf)t) − e^(−t) over the fog's
    // optical depth t and D(end) = open_radiance, the field at the surface toward the camera
    // (docs/fog.md, "Surfaces seen through the fog").
    Transmittance forward_gain{0.0f};
    Radiance open_radiance{0.0f};
    MediumStretch whole() const { return {near.transmittance * beyond, near.in_scattered}; }
  };
  static constexpr double kSeenDepth = 10.0;
  Along along(const Ray& ray, double distance) const;

  // With multiple scattering, what a surface at the end of `ray` (at `distance`, facing
  // `normal`, reaching `extent_m` about the point) changes in the fog's light in front
  // of it: it hides the open field's light from behind its plane and gives its own
  // (media/fog_behind_surface.h). Nothing in the paper's mode.
  FogHiddenBehind hidden_behind(const Ray& ray, double distance, const Vec3& normal, double extent_m) const;
  bool hides_light_behind_surfaces() const { return behind_ != nullptr; }
  // Whether views lose the field's sun-side light in the buildings' shadows (a sun
  // lights the fog and the field is multiply scattered).
  bool takes_sun_side_out_in_shadows() const { return !row_sun_side_.empty(); }

  // The fog's transmittance toward the sun from a point (0 if the sun is down).
  Transmittance sun_transmittance(const Vec3& point) const;
  // The same for the fast method's sunlit surfaces: with multiple scattering the light
  // of the phase function's forward part stays in the beam (the scaled depth of
  // media/fog_diffuse_field.h), as in the beams of the fog itself.
  Transmittance sun_beam_transmittance(const Vec3& point) const;
  // The share of the sky light that still reaches altitude z through the fog, per bin
  // (J(z) over J without fog).
  Transmittance sky_light_share(double z) const;
  // With multiple scattering, the light that reaches surfaces inside the layer by
  // direction (what lights them in place of the sky times sky_light_share); null in the
  // paper's mode.
  const FogSurfaceLight* surface_light() const { return surface_light_.get(); }
  // With multiple scattering, what a shaded surface misses of the fog's sunlight by
  // direction (media/fog_shadowed_sunlight.h; nothing with the sun down); else null.
  const FogShadowedSunlight* shadowed_sunlight() const { return shadowed_sunlight_.get(); }

  const FogLayer& layer() const { return layer_; }
  // The factor on the optical depth toward the sun of the beams (FogSkyLight).
  double sun_depth_scale() const { return sky_light_.sun_depth_scale(); }

 private:
  FogLayer layer_;
  Vec3 to_sun_;
  Spectrum sun_above_fog_;  // the sun's direct normal irradiance at the layer's top
  SunShadowVolumes shadows_;
  FogSkyLight sky_light_;
  // With multiple scattering; refers to layer_, shadows_, sky_light_'s field.
  std::unique_ptr<FogShadowedSunlight> shadowed_sunlight_;
  std::unique_ptr<FogSurfaceLight> surface_light_;  // refers to sky_light_
  std::unique_ptr<FogBehindSurfaces> behind_;       // refers to layer_ and sky_light_

  // The sky light scattered toward the camera along rays of elevation row i, up to
  // distance slice k: slices at length_i·(k/K)², length_i where the ray leaves the layer,
  // read between slices by the fog's transmittance.
  static constexpr int kElevationRows = 257, kDistanceSlices = 48;
  // J(z)/J without fog at altitudes evenly spaced through the layer.
  static constexpr int kShareAltitudes = 129;
  std::vector<Spectrum> sky_share_;
  static double row_elevation(int row);  // radians, crowded toward the horizontal
  // A camera ray's place in the tables, the same all along it: its two elevation rows
  // and the weight of the upper one, and cos(mφ) of its relative azimuth φ per term.
  struct CameraRay {
    int row;
    float upper;
    std::array<float, FogSkyLight::kMaxTerms> azimuth_weights;
  };
  CameraRay camera_ray(const Vec3& direction) const;
  // What a table (row_inscatter_ or row_sun_side_) gathered along the ray up to
  // `distance`; `depth` is the clearest bin's optical depth there, by which the slices
  // are read (the rows around the ray, a fraction of a degree away, are taken to have
  // the same).
  Spectrum from_camera(const CameraRay& ray, double distance, double depth, const std::vector<Spectrum>& table) const;
  // With multiple scattering: the field's light from the sun's side of the sky, which the
  // buildings hide from the points in their shadow, over the ray's `shadowed` parts (none
  // before `begin`, where the ray enters the layer); from the camera's table when
  // `camera` is given.
  Spectrum sun_side_light_in_shadow(const Ray& ray, const std::vector<Interval>& shadowed, double begin,
                                    const CameraRay* camera) const;
  double min_sigma_;  // σ of the clearest bin (m⁻¹ per unit density)
  Vec3 camera_;
  std::vector<double> row_length_;
  int terms_ = 1;                        // azimuthal terms of the sky light's source (FogSkyLight)
  std::vector<Spectrum> row_inscatter_;  // [row][slice][term]
  std::vector<Spectrum> row_sun_side_;   // the same for the source's sun-side part (empty without)
  std::vector<double> row_depth_;        // [row][slice]: the clearest bin's optical depth from the camera
  // The clearest bin's optical depth from the camera along a ray of vertical cosine z_v.
  double clearest_depth(double z_v, double distance) const;
};

}  // namespace skylit
