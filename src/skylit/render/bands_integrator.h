// The paper's fast, noise-free method (`bands`), one ray at a time: the radiance that
// arrives at the camera along a view ray. The sun attenuated on its way to each
// surface, with hard shadows; the sky dome's band sources on surfaces, hidden by
// obstacles that send back their own light (sky/sky_light.h); lamps; mirror reflections;
// the sky and the sun's disc where the ray meets no object; all seen through the air,
// the fog and the clouds on the way (view_path.h).
//
// The image loop (image_loop.h) and the tests call the same function, radiance(); the
// loop only hands it what it found once for the whole image (the surface a pixel's
// centre sees, the cached sky light and lamp glow), and each of these is computed
// exactly where it is not given (but for the sky light of what stands for one pixel or
// less: with fewer directions, kOnePixelDirections).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "skylit/render/lamp_glow_image.h"
#include "skylit/render/obstacle_materials.h"
#include "skylit/render/obstacle_sky_light.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/render/primary_hits.h"
#include "skylit/render/reflected_sun.h"
#include "skylit/render/surface_cache.h"
#include "skylit/render/tile_sliver_values.h"
#include "skylit/render/view_path.h"
#include "skylit/sky/sky_light.h"

namespace skylit {

// What the image loop found once for the whole image, that a sample may use instead of
// computing it: any of them may be absent.
struct ImageCaches {
  const SurfaceCache* sky_light = nullptr;
  const LampGlowImage* glow = nullptr;
};

// What lies between the camera and the surface is found once per pixel and shared by the
// pixel's samples that lie within 1 % of the same distance (their directions differ by
// under a pixel); a sample on another surface at another depth gets its own.
class PixelViewPath {
 public:
  template <typename Make>
  const ViewPath& for_distance(double distance, Make&& make) {
    // A surface never shares the sky's path, nor the sky a surface's: |d − ∞| ≤ 0.01·∞
    // would hold, and a surface seen through the sky's path (no aerial perspective) made
    // a one-pixel line where a ground plane's edge meets the sky.
    const bool same = valid_ && std::isinf(distance) == std::isinf(distance_) &&
                      (std::isinf(distance) || std::abs(distance - distance_) <= 0.01 * distance_);
    if (!same) {
      path_ = make();
      distance_ = distance;
      valid_ = true;
    }
    return path_;
  }

 private:
  bool valid_ = false;
  double distance_ = 0;
  ViewPath path_;
};

// A sample's place in the image and what it may take from the image's caches.
struct SampleContext {
  double image_x = 0, image_y = 0;  // pixels, for the caches' look-ups
  ImageCaches caches;
  PixelViewPath* pixel_path = nullptr;  // none: the view path is found for this ray alone
  // Where sky light the cache has no value for is kept and shared within the tile; none:
  // each such sample computes its own.
  TileSliverValues* slivers = nullptr;
};

class BandsIntegrator {
 public:
  explicit BandsIntegrator(const PreparedScene& scene);

  // What a camera ray meets first.
  PrimaryHit first_hit(const Ray& ray) const;

  // Radiance arriving along `ray` (W m⁻² sr⁻¹ nm⁻¹), whose first hit is `hit`.
  Radiance radiance(const Ray& ray, const PrimaryHit& hit, const SampleContext& context) const;
  // The same, exactly: traced here, with nothing taken from caches.
  Radiance radiance(const Ray& ray) const { return radiance(ray, first_hit(ray), {}); }

  // The sky's light at a surface point seen from `viewer`, exactly, the sun reflected
  // onto it by rough glossy facades, and what it changes in the fog's light in front of
  // it (what the surface cache holds).
  CachedSkyLight sky_light_at(const SurfacePoint& point, const Vec3& viewer) const {
    return sky_light_at(*sky_light_, *sky_light_, point, viewer);
  }

  // The same with kOnePixelDirections: for a value that stands for one pixel at most (the
  // cache's per-pixel level).
  CachedSkyLight sky_light_for_one_pixel(const SurfacePoint& point, const Vec3& viewer) const {
    return sky_light_at(*one_pixel_sky_light_, *one_pixel_sky_light_, point, viewer);
  }

  // The same for a point whose sky light is a small part of what its pixel shows (the
  // image cache's choice, render/image_loop.cpp): the diffuse part with
  // kOnePixelDirections and the obstacles lit as the point itself
  // (ObstacleLight::lit_as_the_point), without patches of their own sky
  // (render/obstacle_sky_light.h); the glossy part as sky_light_for_one_pixel's, since a
  // metal shows the sky, not the lamps' diffuse light. In scenes with lamps in fog only.
  CachedSkyLight faint_sky_light_at(const SurfacePoint& point, const Vec3& viewer) const {
    return sky_light_at(*faint_sky_light_, *one_pixel_sky_light_, point, viewer);
  }

  // The most diffuse sky light (lx) that could reach the surface at `point`, as it is
  // shown (after the clouds' share): the open sky's (or the fog's field's) on its plane,
  // and what obstacles could send in place of the sky they hide. No lamp light is in the
  // sky-light integrals' obstacles; the light on them is at most E* = E₀ + ρ·E*, E₀ the
  // most the open sky puts on any plane plus the sun's (or the moon's) normal
  // illuminance high above the scene, ρ the scene's brightest diffuse albedo (light
  // going to and fro between bright walls); they send at most ρ·E*. Left out: a glass or
  // metal obstacle mirroring a brighter part of the sky than the one it hides, and an
  // obstacle under a cloud base that lifts its sky light more than the point's (each
  // puts the sky light above the bound by a fraction of it). In scenes with lamps in fog
  // only.
  double sky_light_bound_lx(const SurfacePoint& point) const;

  // Obstruction directions for sky light that stands for one pixel or less: the image
  // cache's per-pixel level (a pixel centre that no grid point covers, shared only by
  // that pixel's antialiasing samples) and a sample whose surface the cache has no
  // value for (a sliver that no pixel centre within 2 pixels sees; shared with the
  // tile's later samples on the same surface within 2 pixels). A quarter of the
  // directions, their sub-cells traced apart only across the aureole
  // (SkyLight::Cells::kMeansAcrossTheAureole); what this changes in the image is
  // measured against the exact sky light by tests/render/sky_light_accuracy_test.cpp
  // (docs/sky-light.md).
  static constexpr int kOnePixelDirections = 256;

  // With `render.obstacle_light` "own_sky": the directions of the sky-light integrals
  // that light the obstacles a point's sky light meets (render/obstacle_sky_light.h),
  // the first for the obstacles of the
  // surfaces seen, the next for theirs; the last level's obstacles are lit as the point
  // that sees them (ObstacleLight::lit_as_the_point). Each level is one more bounce of light
  // between buildings; two and the closure put a canyon's shaded wall within 3 % of the
  // path tracer for height/width 1–4 (tests/render/canyon_light_test.cpp).
  static constexpr std::array<int, 2> kObstacleLevelDirections{256, 128};

  // The sunlight that glass and metal facades reflect onto the surface at `point`
  // (W m⁻² nm⁻¹, on the side its normal faces): the rough facades' from `cached`
  // (sky_light_at or its cache), the mirrors' traced here.
  Irradiance reflected_sun(const SurfacePoint& point, const CachedSkyLight& cached) const;

  const SkyLight& sky_light() const { return *sky_light_; }
  // How many obstacle patches each level holds (none with the open-sky obstacle light).
  std::vector<size_t> obstacle_patch_counts() const;
  // The sky light as sky_light() finds it, with `directions` directions instead: for
  // checking the quadrature's own convergence (tests/render/sky_light_cache_examples_test.cpp).
  std::unique_ptr<SkyLight> sky_light_with(int directions) const;
  // The glass and metal facet groups that reflect the sun onto other surfaces.
  const ReflectedSun& facades() const { return *reflected_sun_; }

  // The irradiance (W m⁻² nm⁻¹) on the surface at `point`, on the side its normal faces:
  // the sun if it reaches it, the sky's diffuse irradiance (from sky_light_at or its
  // cache) dimmed by fog and clouds above, the sun reflected by facades, and the lamps;
  // what the Lambertian shading uses.
  Irradiance irradiance(const SurfacePoint& point, const CachedSkyLight& sky_light) const;

 private:
  const Material& material_of(const SurfacePoint& point) const { return scene_.material(point.material); }
  // A sky-light integral of `directions` directions whose obstacles are lit by the
  // obstacle sky light's `level` (element_obstacle_light; past the last level, as the
  // point itself).
  std::unique_ptr<SkyLight> sky_light_looking_up(int level, int directions,
                                                 SkyLight::Cells cells = SkyLight::Cells::kCentres,
                                                 SkyLight::Turning turning = SkyLight::Turning::kNone) const;
  // With the diffuse part from `diffuse_from`, the glossy part from `glossy_from`.
  CachedSkyLight sky_light_at(const SkyLight& diffuse_from, const SkyLight& glossy_from, const SurfacePoint& point,
                              const Vec3& viewer) const;
  // How far the plane of a surface point reaches about it (m), up to kLargestSurfaceExtentM:
  // how much of the fog's light from behind it the surface hides (FogMedium::hidden_behind).
  static constexpr double kLargestSurfaceExtentM = 512;
  double surface_extent(const SurfacePoint& point) const;
  ViewPath view_path(const Ray& ray, double distance) const;
  // The sun's direct normal irradiance at a surface point if it reaches it (0 in
  // shadow or behind the surface); given `sunlit_share`, that share of it instead of
  // a shadow ray's verdict.
  Irradiance sun_reaching(const SurfacePoint& point, std::optional<float> sunlit_share = std::nullopt) const;
  // Whether something stands between the sun and a point on a surface facing `normal`
  // (the shadow ray of sun_reaching and of the obstacles' patches).
  bool sun_blocked(const Vec3& position, const Vec3& normal) const;
  // The light a surface sends toward the camera, before the air and fog on the way.
  // `parts`, if given: the part of it the surface leaves about alike toward every
  // direction (all but the sun's highlight and the mirror's view), and whether the sun
  // reaches it.
  struct LeavingParts {
    Radiance alike_everywhere{0.0f};
    bool sun_reaches = false;
  };
  Radiance shade(const Ray& ray, const SurfacePoint& point, const CachedSkyLight& sky_light,
                 LeavingParts* parts = nullptr) const;
  // The lamps' glow in fog along the ray: from the glow image if given, else exactly.
  Radiance lamp_glow(const Ray& ray, const PrimaryHit& hit, const SampleContext& context) const;
  // The sky light's share that gets through the clouds and the fog to a point, on a
  // surface facing `facing` (1 without either; the fog's by altitude, the clouds' by
  // ground position and facing, cloud_sky_share.h). For the light from one direction,
  // the share of a surface facing it.
  Transmittance sky_share(const Vec3& point, const Vec3& facing) const;
  // The clouds' part of it.
  Transmittance clouds_share(const Vec3& point, const Vec3& facing) const;
  // The same for the sky light the sky-light integrals give (diffuse and glossy): without
  // the fog's share where the fog's multiple scattering lights the point
  // (SkyLight::lights_in_fog).
  Transmittance diffuse_share(const SurfacePoint& point) const;
  // The sky's light arriving at `point` from `direction` where nothing hides it: dimmed
  // by the fog's share, or the fog's own light where its multiple scattering lights the
  // point; and by the clouds.
  Radiance sky_seen_from(const Vec3& point, const Vec3& direction) const;
  // What a mirror (window glass) shows in its mirror direction: an obstacle's light,
  // or the sky and the sun.
  Radiance mirrored(const SurfacePoint& point, const Vec3& direction) const;
  // The light a hit obstacle sends back along `ray`: its Lambertian part, lit by the
  // sun and by `sky`; and for glass and metal, the sky or the Lambertian obstacle it
  // mirrors (its Fresnel reflectance times the light from the mirror direction: a glossy
  // lobe's blur is left out, the sky being smooth; the sun it reflects is
  // ReflectedSun's, but a broad lobe's (kBroadLobeRoughness) is added here, toward the
  // ray's origin), the latter lit by obstacle_sky at `level`. `body` is the material of
  // the obstacle's Lambertian part (textured or not); what it mirrors is seen by its
  // materials' means.
  // `sunlit_share`: the sun's share of the obstacle's patch (render/obstacle_sky_light.h)
  // instead of a shadow ray from the point.
  Radiance obstacle_radiance(const Ray& ray, const SurfacePoint& point, const Material& body, const Irradiance& sky,
                             int level, std::optional<float> sunlit_share = std::nullopt) const;
  // The same for a ray of a sky-light integral, which stands for a sky element: textures
  // by their means (render/obstacle_materials.h); its sky light the open sky's, or with
  // "own_sky" the obstacle sky light's `level`, or where that has none the integral's own
  // (ObstacleLight::lit_as_the_point). `element_width_rad`: the element's width.
  ObstacleLight element_obstacle_light(const Ray& ray, const Hit& hit, int level, double element_width_rad) const;
  // `sun`: the direct sun reaching the point, on a plane facing it (sun_reaching).
  Radiance lambertian_obstacle_radiance(const Ray& ray, const SurfacePoint& point, const Material& material,
                                        const Irradiance& sky, const Irradiance& sun) const;
  // The sky light on an obstacle seen other than by an integral (in a mirror): the
  // obstacle sky light's `level` where it has a patch, else the open sky's.
  Irradiance obstacle_sky(const Ray& ray, const Hit& hit, const SurfacePoint& point, int level) const;
  // The size of what the image resolves at `point`: the cache's finest spacing (4 pixels)
  // at its distance from the camera, m. No obstacle patch need be finer for a sky-light
  // integral there, whose result is interpolated over that much.
  double resolved_m(const Vec3& point) const {
    return 4 * scene_.pixel_angle_rad() * length(point - scene_.scene().camera.position);
  }
  // The sky's (or a multiply scattering fog's) irradiance on a surface where nothing hides it.
  Irradiance open_sky_irradiance(const SurfacePoint& point) const;

  const PreparedScene& scene_;
  const SkyModel& sky_;
  Vec3 to_sun_;
  const FogSurfaceLight* fog_light_;  // with the fog's multiple scattering; else null
  std::unique_ptr<SkyLight> sky_light_;
  std::unique_ptr<SkyLight> one_pixel_sky_light_;  // kOnePixelDirections
  std::unique_ptr<SkyLight> faint_sky_light_;      // the same, obstacles lit as the point (below)
  // Per level of kObstacleLevelDirections: the integrals whose values obstacle_sky_ keeps.
  std::vector<std::unique_ptr<SkyLight>> obstacle_sky_lights_;
  std::unique_ptr<ObstacleSkyLight> obstacle_sky_;
  std::unique_ptr<ReflectedSun> reflected_sun_;
  std::vector<Material> obstacle_materials_;  // per scene material: what obstacle rays see
  // Per scene material: whether its glossy lobe is at least kBroadLobeRoughness wide,
  // so that obstacle rays carry the sun it reflects (reflected_sun.h).
  std::vector<char> broad_lobe_;
  // With lamps in fog only (what the image cache's glow needs): sky_light_bound_lx's
  // obstacles' part, and the integral of faint_sky_light_at.
  double obstacles_bound_lx_ = 0;
};

}  // namespace skylit
