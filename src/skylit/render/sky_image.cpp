#include "skylit/render/sky_image.h"

#include <cmath>

#include <tbb/parallel_for.h>

#include "skylit/spectrum/cie.h"

namespace skylit {

std::optional<Vec3> sky_projection_direction(SkyProjection projection, int size, double x, double y) {
  if (projection == SkyProjection::equirect) {
    const double azimuth = 360.0 * x / (2.0 * size);
    const double altitude = 90.0 - 180.0 * y / size;
    return direction_from_altitude_azimuth(altitude, azimuth);
  }
  const double dx = (x - 0.5 * size) / (0.5 * size), dy = (y - 0.5 * size) / (0.5 * size);
  const double rho = std::hypot(dx, dy);
  if (rho > 1.0) return std::nullopt;
  // Seen from below: north up, east to the left.
  const double azimuth = degrees(std::atan2(-dx, -dy));
  return direction_from_altitude_azimuth(90.0 * (1.0 - rho), azimuth);
}

XyzImage render_sky(const SkyModel& sky, SkyProjection projection, int size) {
  const int width = projection == SkyProjection::equirect ? 2 * size : size;
  XyzImage image(width, size);
  tbb::parallel_for(0, size, [&](int row) {
    for (int column = 0; column < width; ++column) {
      Radiance sum;
      for (int s = 0; s < 4; ++s) {
        const int sub_x = s % 2, sub_y = s / 2;  // a 2 × 2 grid of samples in the pixel
        const auto direction =
            sky_projection_direction(projection, size, column + 0.25 + 0.5 * sub_x, row + 0.25 + 0.5 * sub_y);
        if (direction) sum += sky.sky_radiance(*direction) + sky.sun_radiance(*direction);
      }
      image.set(column, row, xyz_from_spectrum((sum * 0.25f).spectrum()));
    }
  });
  return image;
}

}  // namespace skylit
