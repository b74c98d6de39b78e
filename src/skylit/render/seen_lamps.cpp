#include "skylit/render/seen_lamps.h"

#include <cmath>
#include <optional>
#include <utility>

namespace skylit {

void add_seen_lamps(const PreparedScene& scene, const ImageCamera& camera, Film& film) {
  if (!scene.lamps()) return;
  const SceneLamps& lamps = *scene.lamps();
  const Vec3& eye = scene.scene().camera.position;
  for (size_t i = 0; i < lamps.size(); ++i) {
    const Vec3& lamp = lamps.position(i);
    const std::optional<std::pair<double, double>> at = camera.project(lamp);
    if (!at) continue;
    const int x = static_cast<int>(std::floor(at->first)), y = static_cast<int>(std::floor(at->second));
    if (x < 0 || y < 0 || x >= film.width() || y >= film.height()) continue;
    const Vec3 to_lamp = lamp - eye;
    const double distance = length(to_lamp);
    if (!(distance > 0)) continue;
    const Vec3 direction = to_lamp / distance;
    if (scene.tracer().occluded(Ray{eye, direction, 0.0, distance * (1 - 1e-6)})) continue;
    const Irradiance irradiance =
        lamps.irradiance_from(i, eye) * scene.sky().aerial_perspective(direction, distance).transmittance;
    film.add_point_source(x, y, irradiance, camera.pixel_solid_angle(x + 0.5, y + 0.5));
  }
}

}  // namespace skylit
