// The march through a cloud (clouds/cloud_march.h): the optical depth against the
// thickness function (vertical rays, exactly) and against a fine reference march (slant
// rays); the bounds on the margin g hold, and skipping with them finds the same
// stretches as evaluating every step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "cloud_test_support.h"
#include "skylit/clouds/cloud.h"
#include "skylit/clouds/cloud_layer.h"

namespace skylit {
namespace {

// Independent reference: midpoint rule on the indicator of the solid with many steps.
double reference_depth(const Cloud& c, const Vec3& o, const Vec3& d, double t0, double t1, int n) {
  const double h = (t1 - t0) / n;
  double len = 0;
  for (int i = 0; i < n; ++i)
    if (c.contains(o + d * (t0 + (i + 0.5) * h))) len += h;
  return c.shape().extinction * len;
}

TEST(CloudOpticalDepth, VerticalRaysEqualSigmaTimesThickness) {
  const Cloud c(wavy_cloud());
  const CloudShape& s = c.shape();
  int checked = 0;
  for (int i = -9; i <= 9; ++i)
    for (int j = -9; j <= 9; ++j) {
      const Vec3 p = local_point(s, i * 130.0, j * 75.0, 0);
      const double t = c.thickness(p.x, p.y);
      const double expected = s.extinction * t;
      const double up = c.optical_depth({p.x, p.y, 0}, {0, 0, 1}, 0, kInf);
      const double down = c.optical_depth({p.x, p.y, 5000}, {0, 0, -1}, 0, 1e4);
      if (expected == 0) {
        EXPECT_EQ(up, 0.0);
        EXPECT_EQ(down, 0.0);
        continue;
      }
      ++checked;
      EXPECT_NEAR(up, expected, 1e-6 * expected) << i << ' ' << j;
      EXPECT_NEAR(down, expected, 1e-6 * expected) << i << ' ' << j;
      // Starting inside the cloud, at its mid-plane: half the column.
      const double half = c.optical_depth({p.x, p.y, s.altitude}, {0, 0, 1}, 0, kInf);
      EXPECT_NEAR(half, 0.5 * expected, 1e-6 * expected);
      EXPECT_NEAR(c.transmittance({p.x, p.y, 0}, {0, 0, 1}, 0, kInf), std::exp(-expected), 1e-6 * std::exp(-expected));
    }
  EXPECT_GT(checked, 200);
}

TEST(CloudOpticalDepth, SlantRaysMatchFineReferenceMarch) {
  const Cloud c(wavy_cloud());
  const CloudShape& s = c.shape();
  const double elevations[] = {80, 45, 20, 5, 1, 0};
  int checked = 0;
  for (double elev : elevations)
    for (int az = 0; az < 360; az += 45) {
      const Vec3 d = direction_from_altitude_azimuth(elev, az);
      for (double off : {-300.0, 0.0, 250.0}) {
        // A ray through a point of the mid-plane near the centre.
        const Vec3 target = local_point(s, off, 0.4 * off, s.altitude + (elev == 0 ? 50.0 : 0.0));
        const Vec3 o = target - d * 5000.0;
        double t0, t1;
        if (!c.clip(o, d, 0, kInf, t0, t1)) continue;
        const double got = c.optical_depth(o, d, 0, kInf);
        const double ref = reference_depth(c, o, d, t0, t1, 100000);
        if (ref < 1e-3) continue;
        ++checked;
        EXPECT_NEAR(got, ref, 3e-3 * ref + 1e-4) << "elev " << elev << " az " << az << " off " << off;
      }
    }
  EXPECT_GT(checked, 80);
}

TEST(CloudOpticalDepth, TransmittanceIsExpOfSigmaT) {
  CloudShape s;  // no waves: T = T_max √(1 − r²)
  const Cloud c(s);
  for (double r : {0.0, 0.3, 0.6, 0.9}) {
    const Vec3 p = local_point(s, r * s.semi_axis_a, 0, 0);
    const double t = s.max_thickness * std::sqrt(1 - r * r);
    EXPECT_NEAR(c.thickness(p.x, p.y), t, 1e-9 * t);
    EXPECT_NEAR(c.transmittance(p, {0, 0, 1}, 0, kInf), std::exp(-s.extinction * t), 1e-7);
  }
}

// The march skips runs of steps where cloud_margin_bounds proves the sign of g = T/2 − |z − z_mid|
// (docs/clouds.md). Clouds to test it on: generated Gardner clouds (as in the renderer),
// the wavy test cloud with other falloff exponents (p = 0: a step at the rim; p < 1: an
// infinite slope there), and a texture clipped at 0 (Σ|a| ≥ 1: no curvature bound).
std::vector<CloudShape> march_test_shapes() {
  std::vector<CloudShape> shapes;
  CloudLayerSettings layer;
  layer.coverage = 0.5;
  layer.half_extent = 3000;
  layer.seed = 11;
  const CloudLayer generated = CloudLayer::generate(layer);
  for (const Cloud& c : generated.clouds())
    if (shapes.size() < 5) shapes.push_back(c.shape());
  CloudShape small;  // like the third cloud of examples/fig10a.json
  small.semi_axis_a = 380;
  small.semi_axis_b = 260;
  small.rotation = radians(60);
  small.altitude = 1300;
  small.max_thickness = 320;
  add_gardner_waves(small, 5);
  shapes.push_back(small);
  for (double p : {0.5, 0.0, 0.25, 1.0, 2.0}) {
    CloudShape s = wavy_cloud();
    s.falloff_exponent = p;
    shapes.push_back(s);
  }
  CloudShape clipped = wavy_cloud();
  clipped.waves_u = {{0.7, 2 * kPi / 500, 0.3}, {0.5, 2 * kPi / 170, 1.1}};
  shapes.push_back(clipped);
  return shapes;
}

// A random ray near a cloud: from around its bounding volume toward a point of it, at
// any elevation but more often shallow ones.
void random_ray(const Cloud& c, std::mt19937_64& rng, Vec3& o, Vec3& d) {
  auto uni = [&](double a, double b) { return a + (b - a) * cloud_uniform(rng()); };
  const CloudShape& s = c.shape();
  const Vec3 target{s.center_x + uni(-1, 1) * c.extent_x(), s.center_y + uni(-1, 1) * c.extent_y(),
                    s.altitude + uni(-0.6, 0.6) * s.max_thickness};
  const double x = uni(-1, 1);
  d = direction_from_altitude_azimuth(90 * x * x * x, uni(0, 360));
  o = target - d * uni(0, 3 * std::max(c.extent_x(), c.extent_y()));
}

TEST(CloudMarch, MarginBoundsHoldOnDenseSamples) {
  std::mt19937_64 rng(17);
  auto uni = [&](double a, double b) { return a + (b - a) * cloud_uniform(rng()); };
  int intervals = 0, tight = 0;
  for (const CloudShape& shape : march_test_shapes()) {
    const Cloud c(shape);
    for (int k = 0; k < 400; ++k) {
      Vec3 o, d;
      random_ray(c, rng, o, d);
      // Stretches from 20 cm to 3 km (log-uniform) around the target.
      const double len = std::exp(uni(std::log(0.2), std::log(3000.0)));
      const double t0 = length(o - Vec3{shape.center_x, shape.center_y, shape.altitude}) * uni(0.5, 1.0) - 0.5 * len;
      double lo, hi;
      cloud_margin_bounds(c, o, d, t0, t0 + len, lo, hi);
      ASSERT_LE(lo, hi);
      ++intervals;
      if (hi - lo < 0.5 * shape.max_thickness) ++tight;
      for (int i = 0; i <= 500; ++i) {
        const double t = t0 + len * (i + (i < 500 ? uni(0, 1) : 0.0)) / 500;
        const Vec3 p = o + d * t;
        const double g = 0.5 * c.thickness(p.x, p.y) - std::abs(p.z - shape.altitude);
        ASSERT_GE(g, lo - 1e-7) << "cloud p " << shape.falloff_exponent << " len " << len << " t " << t - t0;
        ASSERT_LE(g, hi + 1e-7) << "cloud p " << shape.falloff_exponent << " len " << len << " t " << t - t0;
      }
    }
  }
  // Not vacuous: most stretches are bounded to within half the cloud's thickness.
  std::printf("margin bounds: %d of %d stretches bounded within T_max/2\n", tight, intervals);
  EXPECT_GT(tight, intervals / 2);
}

TEST(CloudMarch, SkippingFindsTheSameStretchesAsEveryStep) {
  std::mt19937_64 rng(5);
  int rays = 0, crossing = 0;
  for (const CloudShape& shape : march_test_shapes()) {
    const Cloud c(shape);
    for (int k = 0; k < 300; ++k) {
      Vec3 o, d;
      random_ray(c, rng, o, d);
      double t0, t1;
      if (!c.clip(o, d, 0, kInf, t0, t1)) continue;
      std::vector<std::pair<double, double>> skipping, every;
      march_cloud_inside(c, o, d, t0, t1, [&](double s0, double s1) { skipping.emplace_back(s0, s1); });
      march_cloud_inside(c, o, d, t0, t1, [&](double s0, double s1) { every.emplace_back(s0, s1); },
                         {.every_step = true});
      ++rays;
      if (!every.empty()) ++crossing;
      ASSERT_EQ(skipping, every) << "cloud p " << shape.falloff_exponent << " ray " << k;
      // optical_depth takes runs proven inside whole: the same sum up to rounding.
      double len = 0;
      for (const auto& [s0, s1] : every) len += s1 - s0;
      EXPECT_NEAR(c.optical_depth(o, d, 0, kInf), shape.extinction * len, 1e-12 * shape.extinction * len);
    }
  }
  EXPECT_GT(crossing, rays / 2);
}

}  // namespace
}  // namespace skylit
