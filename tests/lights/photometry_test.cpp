// Intensity distributions (Type C, IES LM-63-02): the simple shapes, their luminous
// flux against closed forms, bilinear table interpolation, the C symmetries and zero
// beyond the measured γ range.
#include "skylit/lights/photometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "skylit/core/vec3.h"

namespace skylit {
namespace {

TEST(LuminairePhotometry, IsotropicFluxIsFourPiTimesIntensity) {
  const auto d = IntensityDistribution::isotropic(1000);
  EXPECT_DOUBLE_EQ(d.candela(123, 77), 1000);
  EXPECT_NEAR(d.luminous_flux(), 4 * kPi * 1000, 4 * kPi * 1000 * 1e-5);
}

TEST(LuminairePhotometry, CosineFluxIsPiTimesPeakAndNothingGoesUp) {
  const auto d = IntensityDistribution::cosine(500);
  EXPECT_DOUBLE_EQ(d.candela(0, 0), 500);
  EXPECT_NEAR(d.candela(40, 60), 250, 1e-9);
  EXPECT_EQ(d.candela(0, 120), 0);
  EXPECT_NEAR(d.luminous_flux(), kPi * 500, kPi * 500 * 1e-5);
}

TEST(LuminairePhotometry, SpotHasFlatCoreSmoothFalloffAndConeFlux) {
  const auto d = IntensityDistribution::spot(2000, 20, 40);
  EXPECT_DOUBLE_EQ(d.candela(0, 10), 2000);
  EXPECT_DOUBLE_EQ(d.candela(0, 20), 2000);
  EXPECT_NEAR(d.candela(0, 30), 1000, 1e-9);  // smoothstep midpoint
  EXPECT_EQ(d.candela(0, 40), 0);
  double previous = 2000;
  for (double g = 20; g <= 40; g += 0.5) {
    EXPECT_LE(d.candela(0, g), previous + 1e-12);
    previous = d.candela(0, g);
  }
  // A hard-edged cone: Φ = 2π (1 − cos θ) I.
  const auto hard = IntensityDistribution::spot(1000, 30, 30);
  const double expected = 2 * kPi * (1 - std::cos(radians(30))) * 1000;
  EXPECT_NEAR(hard.luminous_flux(), expected, expected * 1e-3);
  EXPECT_THROW(IntensityDistribution::spot(1, 40, 20), std::invalid_argument);
}

TEST(LuminairePhotometry, TableInterpolatesBilinearlyAndIsZeroBeyondGamma) {
  // Quadrant table: C 0, 90; γ 0, 90.
  const auto d = IntensityDistribution::table(CSymmetry::kQuadrant, {0, 90}, {0, 90}, {100, 50, 300, 150});
  EXPECT_DOUBLE_EQ(d.candela(0, 0), 100);
  EXPECT_DOUBLE_EQ(d.candela(45, 45), 0.5 * (75 + 225));
  EXPECT_DOUBLE_EQ(d.candela(270, 0), 300);  // mirrored
  EXPECT_DOUBLE_EQ(d.candela(-90, 0), 300);  // negative C wraps
  EXPECT_EQ(d.candela(0, 91), 0);            // beyond the measured range
  EXPECT_DOUBLE_EQ(d.peak_candela(), 300);
  EXPECT_DOUBLE_EQ(d.scaled(2).candela(45, 45), 300);
}

TEST(LuminairePhotometry, TableRejectsInconsistentInput) {
  EXPECT_THROW(IntensityDistribution::table(CSymmetry::kQuadrant, {0, 45}, {0, 90}, {1, 1, 1, 1}),
               std::invalid_argument);
  EXPECT_THROW(IntensityDistribution::table(CSymmetry::kAxial, {0}, {0, 90}, {1}), std::invalid_argument);
  EXPECT_THROW(IntensityDistribution::table(CSymmetry::kAxial, {0}, {90, 0}, {1, 1}), std::invalid_argument);
  EXPECT_THROW(IntensityDistribution::table(CSymmetry::kAxial, {0}, {0, 90}, {1, -1}), std::invalid_argument);
}

TEST(LuminairePhotometry, TiltTableInterpolatesAndClamps) {
  TiltTable t{1, {0, 45, 90}, {1.0, 0.9, 0.7}};
  EXPECT_DOUBLE_EQ(t.multiplier(0), 1.0);
  EXPECT_NEAR(t.multiplier(67.5), 0.8, 1e-12);
  EXPECT_DOUBLE_EQ(t.multiplier(120), 0.7);
  EXPECT_DOUBLE_EQ(TiltTable{}.multiplier(30), 1.0);
}

}  // namespace
}  // namespace skylit
