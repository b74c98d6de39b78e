// The whole-sky projections of `skylit sky`: where each pixel looks.
#include "skylit/render/sky_image.h"

#include <gtest/gtest.h>

namespace skylit {
namespace {

void expect_direction(const std::optional<Vec3>& d, double altitude_deg, double azimuth_deg) {
  ASSERT_TRUE(d.has_value());
  const Vec3 expected = direction_from_altitude_azimuth(altitude_deg, azimuth_deg);
  EXPECT_NEAR(d->x, expected.x, 1e-9);
  EXPECT_NEAR(d->y, expected.y, 1e-9);
  EXPECT_NEAR(d->z, expected.z, 1e-9);
}

TEST(SkyImage, EquirectRunsClockwiseFromNorthAndTopToBottom) {
  const int n = 100;                                                                      // 200 × 100
  expect_direction(sky_projection_direction(SkyProjection::equirect, n, 0, 50), 0, 0);    // left edge: north
  expect_direction(sky_projection_direction(SkyProjection::equirect, n, 50, 50), 0, 90);  // a quarter: east
  expect_direction(sky_projection_direction(SkyProjection::equirect, n, 100, 25), 45, 180);
  expect_direction(sky_projection_direction(SkyProjection::equirect, n, 150, 75), -45, 270);
  expect_direction(sky_projection_direction(SkyProjection::equirect, n, 10, 0), 90, 18);  // the top row's edge
}

TEST(SkyImage, FisheyeHasNorthUpAndEastLeftSeenFromBelow) {
  const int n = 100;
  expect_direction(sky_projection_direction(SkyProjection::fisheye, n, 50, 50), 90, 0);  // zenith at the centre
  expect_direction(sky_projection_direction(SkyProjection::fisheye, n, 50, 0), 0, 0);    // top: north horizon
  expect_direction(sky_projection_direction(SkyProjection::fisheye, n, 0, 50), 0, 90);   // left: east
  expect_direction(sky_projection_direction(SkyProjection::fisheye, n, 100, 50), 0, 270);
  expect_direction(sky_projection_direction(SkyProjection::fisheye, n, 50, 75), 45, 180);  // halfway down: south, 45°
  EXPECT_FALSE(sky_projection_direction(SkyProjection::fisheye, n, 2, 2).has_value());     // outside the circle
}

}  // namespace
}  // namespace skylit
