#include "skylit/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "skylit/spectrum/cie.h"

namespace skylit {

namespace {

constexpr int kTileSize = 32;

// Offset for rays leaving a surface. Embree works in single precision, so a hit point
// is known to about 1e-7 of the coordinates' magnitude; stay well above that.
double surface_offset(const Vec3& p) {
  return 1e-4 + 2e-6 * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

}  // namespace

Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      to_sun_(direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg)),
      atmosphere_(scene.atmosphere),
      sky_(atmosphere_, to_sun_, scene.camera.position.z) {
  for (const SceneObject& object : scene.objects) {
    tracer_.add_mesh(object.mesh);
    material_of_mesh_.push_back(object.material_index);
  }
  tracer_.commit();
  sky_light_ = std::make_unique<SkyLight>(
      sky_, tracer_, [this](const Ray& ray, const Hit& hit, uint64_t& rays) { return obstacle_radiance(ray, hit, rays); });
}

const Spectrum& Renderer::reflectance_of(const Hit& hit) const {
  return std::get<DiffuseMaterial>(scene_.materials[material_of_mesh_[hit.mesh_id]].material).reflectance;
}

SurfacePoint Renderer::surface_point(const Ray& ray, const Hit& hit) const {
  // Two-sided surfaces: use the side facing the ray's origin.
  Vec3 normal = hit.geometric_normal;
  if (dot(normal, ray.direction) > 0) normal = -normal;
  return {ray.origin + hit.t * ray.direction, normal, hit.t};
}

Spectrum Renderer::sun_irradiance(const SurfacePoint& point, uint64_t& rays) const {
  const double cos_sun = dot(point.normal, to_sun_);
  if (cos_sun <= 0) return Spectrum(0.0f);
  const Spectrum sun = sky_.direct_sun(point.position.z);
  if (sun.is_black()) return sun;
  ++rays;
  const Ray shadow_ray{point.position + surface_offset(point.position) * point.normal, to_sun_};
  if (tracer_.occluded(shadow_ray)) return Spectrum(0.0f);
  return sun * static_cast<float>(cos_sun);
}

Spectrum Renderer::obstacle_radiance(const Ray& ray, const Hit& hit, uint64_t& rays) const {
  const SurfacePoint point = surface_point(ray, hit);
  const Spectrum irradiance = sky_.sky_irradiance(point.normal) + sun_irradiance(point, rays);
  return reflectance_of(hit) * irradiance * static_cast<float>(1.0 / kPi);
}

Spectrum Renderer::shade(const Ray& ray, const Hit& hit, const Spectrum& sky_irradiance, uint64_t& rays) const {
  const SurfacePoint point = surface_point(ray, hit);
  const Spectrum irradiance = sky_irradiance + sun_irradiance(point, rays);
  // The surface's light, dimmed by the air on its way to the camera, plus the air's own.
  const ScatteredLight air = sky_.aerial_perspective(ray.direction, hit.t);
  return reflectance_of(hit) * irradiance * air.transmittance * static_cast<float>(1.0 / kPi) + air.radiance;
}

Spectrum Renderer::radiance(const Ray& ray, uint64_t& rays) const {
  ++rays;
  const std::optional<Hit> hit = tracer_.intersect(ray);
  if (!hit) return sky_.sky_radiance(ray.direction) + sky_.sun_radiance(ray.direction);
  const SurfacePoint point = surface_point(ray, *hit);
  return shade(ray, *hit, sky_light_->diffuse_irradiance(point.position, point.normal, rays), rays);
}

XyzImage Renderer::render(const RenderOptions& options) const {
  const RenderSettings& settings = scene_.render;
  const int width = settings.width, height = settings.height, n = settings.samples_per_axis;
  const PinholeCamera camera(scene_.camera, width, height);
  XyzImage image(width, height);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

  // The sky light at a sparse grid of pixel centres first.
  std::atomic<uint64_t> cache_rays{0};
  std::unique_ptr<SurfaceCache> cache;
  arena.execute([&] {
    cache = std::make_unique<SurfaceCache>(
        width, height,
        [&](int px, int py) -> std::optional<SurfacePoint> {
          const Ray ray = camera.ray_through(px + 0.5, py + 0.5);
          const std::optional<Hit> hit = tracer_.intersect(ray);
          cache_rays.fetch_add(1, std::memory_order_relaxed);
          if (!hit) return std::nullopt;
          return surface_point(ray, *hit);
        },
        [&](const SurfacePoint& p) {
          uint64_t rays = 0;
          const Spectrum e = sky_light_->diffuse_irradiance(p.position, p.normal, rays);
          cache_rays.fetch_add(rays, std::memory_order_relaxed);
          return e;
        });
  });
  rays_traced_.fetch_add(cache_rays.load(), std::memory_order_relaxed);

  const int tiles_x = (width + kTileSize - 1) / kTileSize;
  const int tiles_y = (height + kTileSize - 1) / kTileSize;
  const int tile_count = tiles_x * tiles_y;
  std::mutex progress_mutex;
  int tiles_done = 0;

  auto sample = [&](double x, double y, uint64_t& rays) {
    const Ray ray = camera.ray_through(x, y);
    ++rays;
    const std::optional<Hit> hit = tracer_.intersect(ray);
    if (!hit) return sky_.sky_radiance(ray.direction) + sky_.sun_radiance(ray.direction);
    const SurfacePoint point = surface_point(ray, *hit);
    std::optional<Spectrum> sky_irradiance = cache->interpolate(x, y, point);
    if (!sky_irradiance) sky_irradiance = sky_light_->diffuse_irradiance(point.position, point.normal, rays);
    return shade(ray, *hit, *sky_irradiance, rays);
  };

  auto render_tile = [&](int tile) {
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
    uint64_t rays = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        // A regular n × n grid of samples inside the pixel, averaged with equal weights.
        Spectrum sum;
        for (int sy = 0; sy < n; ++sy)
          for (int sx = 0; sx < n; ++sx) sum += sample(x + (sx + 0.5) / n, y + (sy + 0.5) / n, rays);
        image.set(x, y, xyz_from_spectrum(sum * static_cast<float>(1.0 / (n * n))));
      }
    }
    rays_traced_.fetch_add(rays, std::memory_order_relaxed);
    if (options.on_progress) {
      std::lock_guard lock(progress_mutex);
      options.on_progress(++tiles_done, tile_count);
    }
  };

  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
      for (int tile = range.begin(); tile != range.end(); ++tile) render_tile(tile);
    });
  });
  return image;
}

}  // namespace skylit
