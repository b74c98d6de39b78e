// Delta and ratio tracking through clouds (clouds/cloud_tracking.h) against the closed
// form of a slab and the clouds' own optical depth; all within three standard errors.
#include <gtest/gtest.h>

#include <cmath>

#include "cloud_test_support.h"
#include "skylit/clouds/cloud_layer.h"
#include "skylit/clouds/cloud_tracking.h"

namespace skylit {
namespace {

// A cloud of uniform thickness (no texture, no falloff toward the rim) far wider than
// the rays used: a plane-parallel slab between 1300 m and 1700 m.
CloudShape slab() {
  CloudShape s;
  s.altitude = 1500;
  s.semi_axis_a = s.semi_axis_b = 1e6;
  s.max_thickness = 400;
  s.falloff_exponent = 0;
  s.extinction = 0.005;  // optical depth 2 vertically
  return s;
}

struct Mean {
  double value, standard_error;
};

template <typename F>
Mean mean_of(int n, F&& f) {
  double sum = 0, squares = 0;
  for (int i = 0; i < n; ++i) {
    CounterRandom random(9, 0, static_cast<uint64_t>(i));
    const double v = f(random);
    sum += v;
    squares += v * v;
  }
  const double m = sum / n;
  return {m, std::sqrt(std::max(0.0, squares / n - m * m) / (n - 1))};
}

TEST(CloudTracking, SlabTransmittanceAndCollisionsFollowBeerLambert) {
  const CloudLayer layer({Cloud(slab())});
  for (double elevation_deg : {90.0, 40.0, 15.0}) {
    const Vec3 o{0, 0, 0}, d = direction_from_altitude_azimuth(elevation_deg, 30);
    const double exact = std::exp(-0.005 * 400 / d.z);
    const Mean t = mean_of(20000, [&](CounterRandom& r) { return estimate_cloud_transmittance(layer, o, d, 1e7, r); });
    EXPECT_NEAR(t.value, exact, 3 * t.standard_error + 1e-9) << elevation_deg;
    const Mean passed = mean_of(
        20000, [&](CounterRandom& r) { return sample_cloud_collision(layer, o, d, 1e7, r).collided ? 0.0 : 1.0; });
    EXPECT_NEAR(passed.value, exact, 3 * passed.standard_error) << elevation_deg;
    // Where collisions fall: the mean height above the slab's base of a truncated
    // exponential of rate σ/sin h over the slab's 400 m.
    const double rate = 0.005 / d.z;  // optical depth per metre of height
    const double expected_height = 1 / rate - 400 * std::exp(-rate * 400) / (1 - std::exp(-rate * 400));
    const Mean height = mean_of(20000, [&](CounterRandom& r) {
      const CloudCollision c = sample_cloud_collision(layer, o, d, 1e7, r);
      return c.collided ? (o + c.distance * d).z - 1300 : expected_height;
    });
    EXPECT_NEAR(height.value, expected_height, 3 * height.standard_error + 1e-6) << elevation_deg;
  }
}

TEST(CloudTracking, TexturedCloudTransmittanceMatchesItsOpticalDepth) {
  // Through a Gardner-textured cloud the estimate's mean equals e^{−τ} with τ from the
  // cloud's march (within 0.5 %: the march's own error at the thickness boundary), for
  // rays through its rim (τ between 0.3 and 3, where e^{−τ} is well sampled).
  const CloudShape shape = wavy_cloud();
  const CloudLayer layer({Cloud(shape)});
  const Vec3 o = local_point(shape, -150, 80, 0);
  int tested = 0;
  for (double u = -1150; u <= 1150; u += 115) {
    const Vec3 target = local_point(shape, u, 0.3 * u, 1500);
    const Vec3 d = normalize(target - o);
    const double tau = layer.clouds()[0].optical_depth(o, d, 0, 1e5);
    if (tau < 0.3 || tau > 3) continue;
    ++tested;
    const Mean t = mean_of(20000, [&](CounterRandom& r) { return estimate_cloud_transmittance(layer, o, d, 1e5, r); });
    EXPECT_NEAR(t.value, std::exp(-tau), 3 * t.standard_error + 5e-3 * std::exp(-tau)) << u << ", τ " << tau;
  }
  EXPECT_GE(tested, 2);
}

}  // namespace
}  // namespace skylit
