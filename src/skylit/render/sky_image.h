// Whole-sky images for `skylit sky`: each pixel's view direction in an equirectangular
// or an upward angular-fisheye projection, and the image of the sky model in it.
#pragma once

#include <optional>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

enum class SkyProjection {
  // 2N × N: azimuth 0° (north) at the left edge, clockwise (east at a quarter of the
  // width); altitude +90° at the top row's edge to −90° at the bottom's.
  equirect,
  // N × N angular fisheye looking up: zenith at the centre, the horizon on the inscribed
  // circle, north at the top, east on the left (as seen from below).
  fisheye,
};

// The view direction (world frame) through image position (x, y) in pixels; none
// outside the fisheye's circle.
std::optional<Vec3> sky_projection_direction(SkyProjection projection, int size, double x, double y);

// The sky and the sun's disc, 2 × 2 samples a pixel; black outside the fisheye circle.
XyzImage render_sky(const SkyModel& sky, SkyProjection projection, int size);

}  // namespace skylit
