// Renders a scene into an image of absolute CIE XYZ (Y in cd/m²).
//
// Light from the atmosphere model (atmosphere/atmosphere.h): the sun attenuated on its
// way to each surface, with hard shadows; the sky dome's band sources on Lambertian
// surfaces, hidden by obstacles that send back their own light (sky/sky_light.h), kept
// in a screen-space cache (surface_cache.h); the sky and the sun's disc where pixels see
// no object; and the aerial perspective between the camera and every surface. Pixels
// are computed independently on a fixed grid of samples, in tiles in parallel, so the
// output does not depend on the number of threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/clouds/cloud_layer.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/spectrum/xyz_image.h"
#include "skylit/render/camera.h"
#include "skylit/render/fog_medium.h"
#include "skylit/render/scene_lamps.h"
#include "skylit/scene/scene.h"
#include "skylit/render/surface_cache.h"
#include "skylit/sky/sky_light.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

struct RenderOptions {
  int threads = 0;  // 0: as many as the machine has
  // Called now and then with the number of tiles done and the total; from any thread,
  // never concurrently.
  std::function<void(int done, int total)> on_progress;
};

class Renderer {
 public:
  // Builds the acceleration structure and the atmosphere's tables for the scene.
  explicit Renderer(const Scene& scene);
  Renderer(Scene&&) = delete;  // keeps a reference to the scene: it must outlive the renderer

  const SkyModel& sky() const { return sky_; }
  const SkyLight& sky_light() const { return *sky_light_; }

  XyzImage render(const RenderOptions& options = {}) const;

  // Spectral radiance arriving along the ray (W m⁻² sr⁻¹ nm⁻¹), with the sky light
  // computed exactly at the point hit (no cache); adds the rays it traces to `rays`.
  Spectrum radiance(const Ray& ray, uint64_t& rays) const;

  // Rays traced since construction, for the benchmark.
  uint64_t rays_traced() const { return rays_traced_.load(std::memory_order_relaxed); }

 private:
  // The surface point a ray meets, facing the ray's origin.
  SurfacePoint surface_point(const Ray& ray, const Hit& hit) const;
  const Material& material_of(const SurfacePoint& point) const { return scene_.materials[point.material].material; }
  // The sun's direct normal irradiance at a surface point if it reaches it (0 in
  // shadow or behind the surface).
  Spectrum sun_reaching(const SurfacePoint& point, uint64_t& rays) const;
  // The sky's light at a surface point, exactly (what the cache holds).
  CachedSkyLight sky_light_at(const SurfacePoint& point, const Vec3& to_viewer, uint64_t& rays) const;
  // What lies between the camera and a point at `distance` along `ray` (infinite: the
  // sky): the air (aerial perspective; not for the sky, which holds its air already) and
  // the fog.
  struct Between {
    ScatteredLight air;
    FogMedium::Along fog;
    CloudScattering clouds;
    ScatteredLight air_to_clouds;  // the air between the camera and the clouds (sky rays)
  };
  Between between(const Ray& ray, double distance) const;
  // What the camera sees of light leaving a point (or the sky) through what lies between.
  static Spectrum seen_through(const Spectrum& radiance, const Between& between, bool sky);
  // The light a surface sends toward the camera, before the air and fog on the way.
  Spectrum shade(const Ray& ray, const SurfacePoint& point, const CachedSkyLight& sky_light, uint64_t& rays) const;
  // The sky light's share that gets through the clouds and the fog to altitude z (1
  // without either).
  Spectrum sky_share(double z) const {
    return fog_ ? fog_->sky_light_share(z) * cloud_sky_share_ : cloud_sky_share_;
  }
  // The clouds' effect on the sky light that reaches the ground: a horizontal surface's
  // sky irradiance under the clouds over that in a clear sky, per bin.
  Spectrum measure_cloud_sky_share() const;
  // What a mirror (window glass) shows in its mirror direction: an obstacle's light,
  // or the sky and the sun.
  Spectrum mirrored(const SurfacePoint& point, const Vec3& direction, uint64_t& rays) const;
  // Adds each lamp the camera sees directly (not hidden by an object) to the pixel it
  // falls in: a point source's irradiance at the camera spread over that pixel's solid
  // angle, through the fog and the air.
  void add_seen_lamps(XyzImage& image, const PinholeCamera& camera) const;
  // The light a hit obstacle sends back along `ray`, for the sky light's one bounce:
  // its Lambertian part, lit by the sun and the unobstructed sky.
  Spectrum obstacle_radiance(const Ray& ray, const Hit& hit, uint64_t& rays) const;

  const Scene& scene_;
  RayTracer tracer_;
  std::vector<uint32_t> material_of_mesh_;
  Vec3 to_sun_;
  Atmosphere atmosphere_;
  SkyModel sky_;
  std::unique_ptr<SkyLight> sky_light_;
  std::unique_ptr<FogMedium> fog_;  // none without fog
  std::unique_ptr<CloudLayer> clouds_;  // none without clouds
  std::unique_ptr<SceneLamps> lamps_;   // none without lights
  CloudLighting cloud_light_;
  Spectrum cloud_sky_share_{1.0f};
  mutable std::atomic<uint64_t> rays_traced_{0};
};

}  // namespace skylit
