// trace_pixel_layers (pixel_layers.h): the renderer's camera, the scene's tracer.
#include "skylit/render/pixel_layers.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "skylit/render/camera.h"

namespace skylit {

PixelLayers trace_pixel_layers(const PreparedScene& scene) {
  const RenderSettings& settings = scene.scene().render;
  PixelLayers layers;
  layers.width = settings.width;
  layers.height = settings.height;
  const std::size_t n = static_cast<std::size_t>(settings.width) * settings.height;
  layers.object.assign(n, PixelLayers::kNoObject);
  layers.distance_m.assign(n, 0.0f);
  layers.normal.assign(3 * n, 0.0f);
  const ImageCamera camera(scene.scene().camera, settings.width, settings.height);
  tbb::parallel_for(tbb::blocked_range<int>(0, settings.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < settings.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * settings.width + x;
        if (!camera.sees(x + 0.5, y + 0.5)) {
          layers.object[i] = PixelLayers::kNotSeen;
          continue;
        }
        const Ray ray = camera.ray_through(x + 0.5, y + 0.5);
        const std::optional<Hit> hit = scene.tracer().intersect(ray);
        if (!hit) continue;
        const SurfacePoint p = scene.surface_point(ray, *hit);
        layers.object[i] = static_cast<int32_t>(hit->mesh_id);  // meshes are added in object order
        layers.distance_m[i] = static_cast<float>(hit->t);
        for (int c = 0; c < 3; ++c) layers.normal[3 * i + c] = static_cast<float>(p.normal[c]);
      }
  });
  return layers;
}

}  // namespace skylit
