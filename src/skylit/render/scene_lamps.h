// The scene's luminaires as the renderer meets them (§7, Fig. 9): the light they put
// on surfaces, with hard shadows from occlusion rays toward each lamp (a point
// source), dimmed by the fog on the way; and the light the fog scatters from them
// toward the camera, over the parts of each view ray the lamp lights (shadow volumes
// from the lamp: the beams of headlights, the shadows of poles), integrated without
// sampling noise (media/lamp_in_scatter.h).
//
// Not included, and why (docs/lights.md): the clear air's own scattering of lamp light
// (Rayleigh and aerosol scattering coefficients near the ground are 1e-5 to 1e-4 m⁻¹,
// two to three orders below a light fog's); the air's extinction over a street's
// tens of metres (< 1 %); lamp light reflected twice.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "skylit/geometry/point_light_shadow_volumes.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/lights/intensity_map.h"
#include "skylit/media/fog_layer.h"
#include "skylit/media/lamp_in_scatter.h"
#include "skylit/render/surface_cache.h"
#include "skylit/scene/scene.h"

namespace skylit {

// Lamps whose unshadowed light reflected from a point adds up to less than this share of
// the light already found there get no occlusion ray: they are counted as unshadowed.
inline constexpr double kUntestedShare = 0.01;

// A lamp's reach in the fog's glow: its shadow volumes are built, eagerly, for the
// triangles within kLampReachM of it (a city block's triangles beyond are most of them).
// A view ray's glow from the lamp is exact over the chord of the ray within the reach.
// The parts beyond it are integrated unshadowed first: that is an upper bound on what
// they add (shadows only take light away). The lamps' such bounds, smallest first, are
// dropped while their sum stays under kDroppedGlowShare of the glow found within the
// reaches; the others are computed exactly, with volumes over all the lamp's triangles
// (built at the first need). So the lamps' glow on every view ray is exact or below it
// by less than kDroppedGlowShare of it, in luminance; never above it.
inline constexpr double kLampReachM = 100;
inline constexpr double kDroppedGlowShare = 0.01;

class SceneLamps {
 public:
  // `fog` may be null (clear air: no glow); it must outlive this object, as must the
  // lights, the tracer and the meshes.
  // `reach_m`: kLampReachM but in tests (infinity: every glow exact).
  SceneLamps(const std::vector<SceneLight>& lights, const RayTracer& tracer,
             const std::vector<const TriangleMesh*>& meshes, const FogLayer* fog, double reach_m = kLampReachM);

  bool empty() const { return lamps_.empty(); }

  // W m⁻² sr⁻¹ nm⁻¹ a surface point reflects toward the viewer from all lamps
  // (Lambertian and glossy parts).
  // Occlusion rays go to the lamps in order of the radiance they would reflect
  // unshadowed (Lambertian and glossy parts); the last ones, together under
  // kUntestedShare of what was found lit, are counted unshadowed, so the result is
  // exact or above it by less than that share (in the mean over bins).
  Radiance reflected(const SurfacePoint& point, const Material& material, const Vec3& to_viewer) const;

  // W m⁻² sr⁻¹ nm⁻¹ the fog scatters toward the ray's origin from all lamps, over
  // [0, distance] (distance may be infinite); exact or below by less than
  // kDroppedGlowShare of it in luminance (the reach, above).
  Radiance in_scattered(const Ray& ray, double distance) const;

  // W m⁻² nm⁻¹ all lamps put on the surface at `point` (on the side its normal faces),
  // each checked for occlusion: what an illuminance meter laid on it would read.
  Irradiance irradiance_on(const SurfacePoint& point) const;

  // A lamp's spectral irradiance (W m⁻² nm⁻¹) on a plane facing it at `point`, through
  // the fog but not checked for occlusion.
  Irradiance irradiance_from(size_t lamp, const Vec3& point) const;
  size_t size() const { return lamps_.size(); }
  const Vec3& position(size_t lamp) const { return lamps_[lamp].light->luminaire.position(); }

 private:
  struct Lamp {
    const SceneLight* light;
    std::unique_ptr<IntensityMap> map;                 // the luminaire's intensity, for fast look-ups
    std::unique_ptr<PointLightShadowVolumes> volumes;  // with fog only: the triangles within the reach
    std::unique_ptr<LampInScatter> glow;               // with fog only
    // With fog only: all the triangles' volumes, built by the first ray that needs them.
    mutable std::unique_ptr<PointLightShadowVolumes> all_volumes;
    std::unique_ptr<std::once_flag> all_built;
  };
  const PointLightShadowVolumes& all_volumes(const Lamp& lamp) const;
  std::vector<Lamp> lamps_;
  const RayTracer& tracer_;
  const FogLayer* fog_;
  std::vector<ShadowCasterFaces> faces_;  // with fog only: the meshes' faces, for every lamp
  double reach_m_;
};

}  // namespace skylit
