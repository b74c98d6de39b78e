// The solid of a cloud (clouds/cloud_shape.h): the thickness stays within its bounds
// and vanishes outside the ellipse.
#include <gtest/gtest.h>

#include <cmath>

#include "cloud_test_support.h"
#include "skylit/clouds/cloud.h"
#include "skylit/clouds/cloud_layer.h"

namespace skylit {
namespace {

TEST(CloudShape, ThicknessStaysWithinBoundsAndVanishesOutside) {
  const Cloud c(wavy_cloud());
  const CloudShape& s = c.shape();
  double max_seen = 0;
  for (int i = -60; i <= 60; ++i)
    for (int j = -60; j <= 60; ++j) {
      const double u = i * 25.0, v = j * 15.0;
      const Vec3 p = local_point(s, u, v, 0);
      const double t = c.thickness(p.x, p.y);
      const double r2 = (u / s.semi_axis_a) * (u / s.semi_axis_a) + (v / s.semi_axis_b) * (v / s.semi_axis_b);
      ASSERT_GE(t, 0.0);
      ASSERT_LE(t, s.max_thickness);
      if (r2 >= 1) {
        ASSERT_EQ(t, 0.0);
      }
      if (r2 < 0.99) {
        ASSERT_GT(t, 0.0);  // Σ|a| < 1: the footprint is the whole ellipse
      }
      max_seen = std::max(max_seen, t);
    }
  EXPECT_GT(max_seen, 0.3 * s.max_thickness);
}

}  // namespace
}  // namespace skylit
