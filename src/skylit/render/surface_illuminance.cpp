// surface_illuminance (surface_illuminance.h).
#include "skylit/render/surface_illuminance.h"

#include <tbb/parallel_for.h>

#include "skylit/spectrum/cie.h"

namespace skylit {

std::vector<float> surface_illuminance(const PreparedScene& scene, const BandsIntegrator& integrator) {
  const RenderSettings& settings = scene.scene().render;
  const int width = settings.width, height = settings.height;
  const ImageCamera camera(scene.scene().camera, width, height);
  const PrimaryHits hits(camera, width, height, [&](const Ray& ray) { return integrator.first_hit(ray); });
  // Only the diffuse part is needed; the cache's interface carries both.
  const SurfaceCache sky(hits, [&](const SurfacePoint& p) {
    return CachedSkyLight{integrator.sky_light().diffuse_irradiance(p.position, p.normal), Radiance(0.0f)};
  });
  std::vector<float> lux(static_cast<std::size_t>(width) * height, 0.0f);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const SurfacePoint* point = hits.surface(x, y);
      if (!point || !camera.sees(x + 0.5, y + 0.5)) continue;
      std::optional<CachedSkyLight> cached = sky.interpolate(x + 0.5, y + 0.5, *point);
      const Irradiance sky_diffuse = cached ? cached->diffuse_irradiance
                                            : integrator.sky_light().diffuse_irradiance(point->position, point->normal);
      lux[static_cast<std::size_t>(y) * width + x] =
          static_cast<float>(illuminance(integrator.irradiance(*point, sky_diffuse)));
    }
  });
  return lux;
}

}  // namespace skylit
