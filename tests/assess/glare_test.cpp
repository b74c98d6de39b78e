// DGP (assess/glare.h) of a fisheye image with one glare source against the formula of
// Wienold and Christoffersen (2006) evaluated by hand: E_v of a uniform hemisphere plus
// a circular source in closed form, the source's L, ω and Guth's position index.
#include "skylit/assess/glare.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {
namespace {

TEST(Glare, GuthPositionIndexValues) {
  // On the line of sight the index is 1; it grows off axis, faster above than to the side.
  EXPECT_DOUBLE_EQ(guth_position_index(0, 0), 1.0);
  const double above = guth_position_index(30, 0), side = guth_position_index(30, 90);
  // By the formula: τ = 0: exp((35.2 − 1.22)·0.03 + 21·9e-3); τ = 90: exp((35.2 − 28.7001 − 1.22e^−20)·0.03 + (21
  // + 24.0003 − 24.0003)·9e-3)
  EXPECT_NEAR(above, std::exp(33.98 * 0.03 + 21 * 9e-3), 1e-9);
  EXPECT_NEAR(side, std::exp((35.2 - 0.31889 * 90) * 0.03 + (21 + 0.26667 * 90 - 0.002963 * 8100) * 9e-3), 1e-9);
  EXPECT_GT(above, side);
  EXPECT_EQ(guth_position_index(89, 0), 16.0);  // capped as evalglare does
}

TEST(Glare, OneSourceMatchesTheHandComputedDgp) {
  // A 180° equidistant fisheye looking north, level; the half-space in front at 1000
  // cd/m² except a disc of 5° radius at 2·10⁵ cd/m², 30° above the line of sight.
  const int n = 801;
  Camera c;
  c.position = {0, 0, 1.2};
  c.look_at = {0, 10, 1.2};
  c.projection = Projection::fisheye_equidistant;
  c.vertical_fov_deg = 180;
  const ImageCamera camera(c, n, n);
  const double background = 1000, source = 2e5, radius = radians(5), elevation = radians(30);
  const Vec3 to_source{0, std::cos(elevation), std::sin(elevation)};
  XyzImage image(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Vec3 d = camera.ray_through(x + 0.5, y + 0.5).direction;
      const double l = std::acos(std::min(1.0, dot(d, to_source))) < radius ? source : background;
      image.set(x, y, {l, l, l});
    }
  const GlareResult r = daylight_glare_probability(image, camera);

  // By hand: a uniform half-space gives E = π L; the disc adds (L_s − L_b) ω cos 30°, with
  // ω = 2π(1 − cos 5°) (its cosine varies by ±4 % over the disc and averages out to
  // second order). Only the disc exceeds 5 × the mean (~1100 cd/m²).
  const double omega = 2 * kPi * (1 - std::cos(radius));
  const double e_v = kPi * background + (source - background) * omega * std::cos(elevation);
  const double p = guth_position_index(30, 0);
  const double dgp =
      5.87e-5 * e_v + 9.18e-2 * std::log10(1 + source * source * omega / (std::pow(e_v, 1.87) * p * p)) + 0.16;
  // 1 %: the tolerance; the pixel grid's edge of the disc (radius 22 px) is the
  // error, ~0.3 % of ω, which moves DGP far less.
  EXPECT_NEAR(r.vertical_illuminance_lx, e_v, 0.01 * e_v);
  EXPECT_NEAR(r.source_solid_angle_sr, omega, 0.02 * omega);
  EXPECT_NEAR(r.dgp, dgp, 0.01 * dgp);
  EXPECT_GT(r.dgp, 0.35);  // this is a bright glare source: "perceptible" or worse
}

TEST(Glare, NoSourceInAUniformViewAndBlackIsFinite) {
  Camera c;
  c.position = {0, 0, 1.2};
  c.look_at = {0, 10, 1.2};
  c.projection = Projection::fisheye_equisolid;
  c.vertical_fov_deg = 180;
  const ImageCamera camera(c, 101, 101);
  XyzImage uniform(101, 101);
  for (int y = 0; y < 101; ++y)
    for (int x = 0; x < 101; ++x) uniform.set(x, y, {100, 100, 100});
  const GlareResult r = daylight_glare_probability(uniform, camera);
  EXPECT_NEAR(r.vertical_illuminance_lx, kPi * 100, 0.01 * kPi * 100);  // equal-area pixels: ~0.5 % edge error
  EXPECT_EQ(r.source_solid_angle_sr, 0);
  EXPECT_NEAR(r.dgp, 5.87e-5 * r.vertical_illuminance_lx + 0.16, 1e-12);
  const GlareResult black = daylight_glare_probability(XyzImage(101, 101), camera);
  EXPECT_DOUBLE_EQ(black.dgp, 0.16);
}

}  // namespace
}  // namespace skylit
