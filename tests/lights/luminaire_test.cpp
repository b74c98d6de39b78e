// Luminaire placement and direct illuminance (IES LM-63-02 Type C frame): the 40 lx
// check under an isotropic 1000 cd source at 5 m, the cosine-inverse-square law off
// axis, the frame's C0/C90 axes, a rotated or re-aimed luminaire's peak, and tilt.
#include "skylit/lights/luminaire.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace skylit {
namespace {

void expect_vec_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Luminaire, FortyLuxFiveMetresBelowIsotropicThousandCandela) {
  const Luminaire lamp({0, 0, 5}, IntensityDistribution::isotropic(1000));
  const double e = lamp.illuminance({0, 0, 0}, {0, 0, 1});
  EXPECT_NEAR(e, 40.0, 40.0 * 0.005);
  EXPECT_NEAR(e, 40.0, 1e-12);
}

TEST(Luminaire, FollowsCosineInverseSquareLawOffAxis) {
  const Luminaire lamp({2, -1, 5}, IntensityDistribution::isotropic(1000));
  for (double r : {0.5, 1.0, 3.0, 5.0, 10.0, 30.0}) {
    const Vec3 p{2 + r * 0.6, -1 + r * 0.8, 0};
    const double d = std::sqrt(r * r + 25);
    const double expected = 1000 * (5 / d) / (d * d);
    EXPECT_NEAR(lamp.illuminance(p, {0, 0, 1}), expected, expected * 1e-12) << r;
  }
  // A wall facing the lamp: cos θ from its own normal; a surface facing away gets 0.
  const Vec3 wall_point{5, -1, 5};
  EXPECT_NEAR(lamp.illuminance(wall_point, {-1, 0, 0}), 1000.0 / 9.0, 1e-9);
  EXPECT_EQ(lamp.illuminance(wall_point, {1, 0, 0}), 0.0);
  EXPECT_EQ(lamp.illuminance({2, -1, 5}, {0, 0, 1}), 0.0);
  // A cosine emitter adds a second cos: E = I0 cos² θ / d².
  const Luminaire lambert({0, 0, 5}, IntensityDistribution::cosine(1000));
  const double d = std::sqrt(4.0 * 4.0 + 25);
  EXPECT_NEAR(lambert.illuminance({4, 0, 0}, {0, 0, 1}), 1000 * (25 / (d * d)) / (d * d), 1e-12);
}

TEST(Luminaire, DefaultFrameIsC0EastC90NorthNadirDown) {
  const Luminaire lamp({0, 0, 0}, IntensityDistribution::isotropic(1));
  expect_vec_near(lamp.world_direction(0, 0), {0, 0, -1}, 1e-15);
  expect_vec_near(lamp.world_direction(0, 90), {1, 0, 0}, 1e-15);
  expect_vec_near(lamp.world_direction(90, 90), {0, 1, 0}, 1e-15);
  expect_vec_near(lamp.world_direction(0, 180), {0, 0, 1}, 1e-15);
  const PhotometricAngles a = lamp.photometric_angles({-1, -1, -std::sqrt(2.0)});
  EXPECT_NEAR(a.c_deg, 225, 1e-12);
  EXPECT_NEAR(a.gamma_deg, 45, 1e-12);
  EXPECT_THROW(Luminaire({0, 0, 0}, IntensityDistribution::isotropic(1), {0, 0, 0}), std::invalid_argument);
}

// A table with its only peak at C0, γ60 (no symmetry).
IntensityDistribution peaked_at_c0_gamma60() {
  std::vector<double> values(4 * 7, 10.0);
  values[0 * 7 + 2] = 1000;  // C0, γ60
  return IntensityDistribution::table(CSymmetry::kNone, {0, 90, 180, 270}, {0, 30, 60, 90, 120, 150, 180}, values);
}

// The world direction of the brightest sample on a 5° grid of the sphere.
Vec3 brightest_direction(const Luminaire& lamp) {
  Vec3 best;
  double best_value = -1;
  for (int polar = 0; polar <= 180; polar += 5)
    for (int azimuth = 0; azimuth < 360; azimuth += 5) {
      const double t = radians(polar), p = radians(azimuth);
      const Vec3 d{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), -std::cos(t)};
      const double v = lamp.intensity(d);
      if (v > best_value) best_value = v, best = d;
    }
  return best;
}

TEST(Luminaire, RotationAboutAimMovesPeakCounterClockwise) {
  const Luminaire unrotated({0, 0, 6}, peaked_at_c0_gamma60());
  expect_vec_near(brightest_direction(unrotated), {std::sin(radians(60)), 0, -0.5}, 1e-12);
  const Luminaire rotated({0, 0, 6}, peaked_at_c0_gamma60(), {0, 0, -1}, 90);
  expect_vec_near(brightest_direction(rotated), {0, std::sin(radians(60)), -0.5}, 1e-12);
  EXPECT_NEAR(rotated.intensity({0, std::sin(radians(60)), -0.5}), 1000, 1e-9);
  // The brightest ground spot is where that ray meets the ground: 6 tan 60° north.
  const Vec3 spot{0, 6 * std::tan(radians(60)), 0};
  const Vec3 off{6 * std::tan(radians(60)), 0, 0};
  EXPECT_GT(rotated.illuminance(spot, {0, 0, 1}), 10 * rotated.illuminance(off, {0, 0, 1}));
}

TEST(Luminaire, AimCarriesTheFrameByTheSmallestRotation) {
  // Aimed 45° east of nadir: C0 tilts up toward east-and-up, C90 stays north.
  const Vec3 aim = normalize(Vec3{1, 0, -1});
  const Luminaire lamp({0, 0, 0}, IntensityDistribution::spot(500, 10, 20), aim);
  expect_vec_near(lamp.aim(), aim, 1e-15);
  expect_vec_near(lamp.world_direction(0, 0), aim, 1e-15);
  expect_vec_near(lamp.world_direction(0, 90), normalize(Vec3{1, 0, 1}), 1e-12);
  expect_vec_near(lamp.world_direction(90, 90), {0, 1, 0}, 1e-12);
  EXPECT_DOUBLE_EQ(lamp.intensity(aim), 500);
  EXPECT_EQ(lamp.intensity({0, 0, -1}), 0);  // 45° off the beam axis, beyond the 20° cone
  // Aimed straight up: C0 stays east, C90 turns south.
  const Luminaire up({0, 0, 0}, IntensityDistribution::isotropic(1), {0, 0, 2});
  expect_vec_near(up.world_direction(0, 90), {1, 0, 0}, 1e-15);
  expect_vec_near(up.world_direction(90, 90), {0, -1, 0}, 1e-15);
  // Round trip at an arbitrary aim and rotation.
  const Luminaire any({1, 2, 3}, IntensityDistribution::isotropic(1), {0.3, -0.4, -0.8}, 37);
  for (double c : {0.0, 10.0, 135.0, 300.0})
    for (double g : {5.0, 60.0, 170.0}) {
      const PhotometricAngles a = any.photometric_angles(any.world_direction(c, g));
      EXPECT_NEAR(a.c_deg, c, 1e-9);
      EXPECT_NEAR(a.gamma_deg, g, 1e-9);
    }
}

TEST(Luminaire, TiltMultiplierFollowsTheAim) {
  const TiltTable tilt{1, {0, 45, 90}, {1.0, 0.9, 0.7}};
  const Luminaire down({0, 0, 0}, IntensityDistribution::isotropic(100), {0, 0, -1}, 0, tilt);
  EXPECT_DOUBLE_EQ(down.tilt_multiplier(), 1.0);
  const Luminaire tilted({0, 0, 0}, IntensityDistribution::isotropic(100), {1, 0, -1}, 0, tilt);
  EXPECT_NEAR(tilted.tilt_multiplier(), 0.9, 1e-12);
  EXPECT_NEAR(tilted.intensity({0, 0, -1}), 90, 1e-9);
}

}  // namespace
}  // namespace skylit
