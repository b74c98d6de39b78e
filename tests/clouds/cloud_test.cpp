// One cloud as a whole (clouds/cloud.h): finiteness for degenerate inputs, through
// every part (shape, march, sun grid, Eq. 16, layer).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cloud_test_support.h"
#include "skylit/clouds/cloud.h"
#include "skylit/clouds/cloud_layer.h"

namespace skylit {
namespace {

TEST(CloudDegenerate, NoNaNForDegenerateInputs) {
  auto finite = [](const Spectrum& sp) {
    for (int i = 0; i < Spectrum::size(); ++i)
      if (!std::isfinite(sp[i])) return false;
    return true;
  };
  CloudShape flat;
  flat.max_thickness = 0;
  const Cloud zero(flat);
  const Spectrum sky(0.1f);
  const CloudLighting up = flat_light({0, 0, 1});
  EXPECT_EQ(zero.optical_depth({0, 0, 0}, {0, 0, 1}, 0, kInf), 0.0);
  const Spectrum through = zero.radiance({0, 0, 0}, {0, 0, 1}, 0, kInf, sky, up);
  EXPECT_EQ(total(through), total(sky));

  CloudShape pinch;
  pinch.semi_axis_b = 0;
  EXPECT_EQ(Cloud(pinch).optical_depth({0, 0, 0}, {0, 0, 1}, 0, kInf), 0.0);
  CloudShape nan_shape;
  nan_shape.max_thickness = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Cloud(nan_shape).optical_depth({0, 0, 0}, {0, 0, 1}, 0, kInf), 0.0);

  const Cloud c(wavy_cloud());
  const CloudShape& s = c.shape();
  // Sun below the horizon.
  CloudLighting night = flat_light(direction_from_altitude_azimuth(-10, 90));
  EXPECT_EQ(total(default_cloud_ambient(night.sun, night.to_sun)), 0.0f);
  const Spectrum r = c.radiance({s.center_x, s.center_y, 0}, {0, 0, 1}, 0, kInf, sky, night);
  EXPECT_TRUE(finite(r));
  EXPECT_TRUE(std::isfinite(c.sun_transmittance({s.center_x, s.center_y, 1500}, night.to_sun)));
  // Rays parallel to the layer: in the slab, above it, and along the mid-plane.
  for (double z : {s.altitude, s.altitude + 100, s.altitude + 1000, s.altitude - 199.9}) {
    const Vec3 o{s.center_x - 5000, s.center_y, z};
    const double tau = c.optical_depth(o, {1, 0, 0}, 0, kInf);
    EXPECT_TRUE(std::isfinite(tau));
    EXPECT_GE(tau, 0.0);
    EXPECT_TRUE(finite(c.radiance(o, {1, 0, 0}, 0, kInf, sky, up)));
    EXPECT_TRUE(finite(c.radiance(o, {1, 0, 0}, 0, kInf, sky, night)));
  }
  EXPECT_GT(c.optical_depth({s.center_x - 5000, s.center_y, s.altitude}, {1, 0, 0}, 0, kInf), 1.0);
  EXPECT_EQ(c.optical_depth({s.center_x - 5000, s.center_y, s.altitude + 1000}, {1, 0, 0}, 0, kInf), 0.0);
  // Sun exactly along the layer, zero-length segments, reversed intervals.
  EXPECT_TRUE(std::isfinite(c.sun_transmittance({s.center_x, s.center_y, s.altitude}, {1, 0, 0})));
  EXPECT_EQ(c.optical_depth({s.center_x, s.center_y, 0}, {0, 0, 1}, 10, 10), 0.0);
  EXPECT_EQ(c.optical_depth({s.center_x, s.center_y, 0}, {0, 0, 1}, 10, 5), 0.0);
  // A zero sun vector.
  CloudLighting nosun = up;
  nosun.to_sun = {0, 0, 0};
  EXPECT_TRUE(finite(c.radiance({s.center_x, s.center_y, 0}, {0, 0, 1}, 0, kInf, sky, nosun)));
  // Full coverage.
  CloudLayerSettings full;
  full.coverage = 1.0;
  full.half_extent = 3000;
  const CloudLayer layer = CloudLayer::generate(full);
  EXPECT_FALSE(layer.empty());
  EXPECT_TRUE(std::isfinite(layer.sun_transmittance({0, 0, 0}, {0, 0, 1})));
}

}  // namespace
}  // namespace skylit
