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
}

Spectrum Renderer::shade(const Ray& ray, const Hit& hit, uint64_t& rays) const {
  // Two-sided surfaces: use the side facing the viewer.
  Vec3 normal = hit.geometric_normal;
  if (dot(normal, ray.direction) > 0) normal = -normal;
  const Material& material = scene_.materials[material_of_mesh_[hit.mesh_id]].material;
  const Spectrum& reflectance = std::get<DiffuseMaterial>(material).reflectance;

  const Vec3 point = ray.origin + hit.t * ray.direction;
  Spectrum irradiance = sky_.sky_irradiance(normal);
  const double cos_sun = dot(normal, to_sun_);
  if (cos_sun > 0) {
    const Spectrum sun = sky_.direct_sun(point.z);
    if (!sun.is_black()) {
      const Ray shadow_ray{point + surface_offset(point) * normal, to_sun_};
      ++rays;
      if (!tracer_.occluded(shadow_ray)) irradiance += sun * static_cast<float>(cos_sun);
    }
  }
  // The surface's light, dimmed by the air on its way to the camera, plus the air's own.
  const ScatteredLight air = sky_.aerial_perspective(ray.direction, hit.t);
  return reflectance * irradiance * air.transmittance * static_cast<float>(1.0 / kPi) + air.radiance;
}

Spectrum Renderer::radiance(const Ray& ray, uint64_t& rays) const {
  ++rays;
  const std::optional<Hit> hit = tracer_.intersect(ray);
  if (!hit) return sky_.sky_radiance(ray.direction) + sky_.sun_radiance(ray.direction);
  return shade(ray, *hit, rays);
}

XyzImage Renderer::render(const RenderOptions& options) const {
  const RenderSettings& settings = scene_.render;
  const int width = settings.width, height = settings.height, n = settings.samples_per_axis;
  const PinholeCamera camera(scene_.camera, width, height);
  XyzImage image(width, height);

  const int tiles_x = (width + kTileSize - 1) / kTileSize;
  const int tiles_y = (height + kTileSize - 1) / kTileSize;
  const int tile_count = tiles_x * tiles_y;
  std::mutex progress_mutex;
  int tiles_done = 0;

  auto render_tile = [&](int tile) {
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
    uint64_t rays = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        // A regular n × n grid of samples inside the pixel, averaged with equal weights.
        Spectrum sum;
        for (int sy = 0; sy < n; ++sy)
          for (int sx = 0; sx < n; ++sx)
            sum += radiance(camera.ray_through(x + (sx + 0.5) / n, y + (sy + 0.5) / n), rays);
        image.set(x, y, xyz_from_spectrum(sum * static_cast<float>(1.0 / (n * n))));
      }
    }
    rays_traced_.fetch_add(rays, std::memory_order_relaxed);
    if (options.on_progress) {
      std::lock_guard lock(progress_mutex);
      options.on_progress(++tiles_done, tile_count);
    }
  };

  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
      for (int tile = range.begin(); tile != range.end(); ++tile) render_tile(tile);
    });
  });
  return image;
}

}  // namespace skylit
