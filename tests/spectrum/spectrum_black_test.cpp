// Spectrum::is_black stops at the first positive bin; it must say what max_value() <= 0
// says for every spectrum, NaN bins included (a NaN first bin is not black there).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "skylit/spectrum/spectrum.h"

namespace skylit {
namespace {

TEST(SpectrumBlack, AgreesWithTheLargestBinForEverySpectrum) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> kind(0, 5), bin(0, kSpectralBins - 1);
  std::uniform_real_distribution<float> magnitude(1e-30f, 1e3f);
  int black = 0, not_black = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Spectrum s(0.0f);
    // Mostly zero or negative bins, a few positive, zero or negative zero, and NaNs,
    // placed anywhere (the first and last bins included).
    const int changed = 1 + trial % 5;
    for (int k = 0; k < changed; ++k) {
      float& v = s[bin(random)];
      switch (kind(random)) {
        case 0:
          v = magnitude(random);
          break;
        case 1:
          v = -magnitude(random);
          break;
        case 2:
          v = -0.0f;
          break;
        case 3:
          v = std::numeric_limits<float>::quiet_NaN();
          break;
        case 4:
          v = std::numeric_limits<float>::denorm_min();
          break;
        default:
          v = -std::numeric_limits<float>::infinity();
          break;
      }
    }
    const bool expected = s.max_value() <= 0.0f;
    ASSERT_EQ(s.is_black(), expected) << "trial " << trial;
    (expected ? black : not_black)++;
  }
  // Both answers were met often: the comparison meant something.
  EXPECT_GT(black, 2000);
  EXPECT_GT(not_black, 2000);
}

TEST(SpectrumBlack, ANanFirstBinIsNotBlackAndANanLaterBinIsSkipped) {
  Spectrum first_nan(0.0f);
  first_nan[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(first_nan.is_black());
  Spectrum later_nan(0.0f);
  later_nan[kSpectralBins - 1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(later_nan.is_black());
  later_nan[3] = 1e-20f;
  EXPECT_FALSE(later_nan.is_black());
}

}  // namespace
}  // namespace skylit
