// surface_illuminance (surface_illuminance.h).
#include "skylit/render/surface_illuminance.h"

#include <tbb/parallel_for.h>

#include "skylit/spectrum/cie.h"

namespace skylit {

SurfaceIlluminance surface_illuminance(const PreparedScene& scene, const BandsIntegrator& integrator) {
  const RenderSettings& settings = scene.scene().render;
  const int width = settings.width, height = settings.height;
  const ImageCamera camera(scene.scene().camera, width, height);
  const PrimaryHits hits(camera, width, height, [&](const Ray& ray) { return integrator.first_hit(ray); });
  // Only the irradiances are needed; the cache's interface carries the glossy radiance too.
  auto light_at = [&](const SurfacePoint& p) {
    return CachedSkyLight{integrator.sky_light().diffuse_irradiance(p.position, p.normal), Radiance(0.0f),
                          integrator.facades().from_rough(p.position, p.normal)};
  };
  const SurfaceCache sky(hits, [&](const SurfacePoint& p, int, int) { return light_at(p); });
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  SurfaceIlluminance lux{std::vector<float>(pixels, 0.0f), std::vector<float>(pixels, 0.0f)};
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const SurfacePoint* point = hits.surface(x, y);
      if (!point || !camera.sees(x + 0.5, y + 0.5)) continue;
      const std::optional<CachedSkyLight> cached = sky.interpolate(x + 0.5, y + 0.5, *point);
      const CachedSkyLight light = cached ? *cached : light_at(*point);
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      lux.total_lx[i] = static_cast<float>(illuminance(integrator.irradiance(*point, light)));
      lux.reflected_sun_lx[i] = static_cast<float>(illuminance(integrator.reflected_sun(*point, light)));
    }
  });
  return lux;
}

}  // namespace skylit
