// The report's 16-bit logarithmic luminance codes: every value in the range decodes
// within the stated precision, and the ends and non-finite input are handled.
#include "skylit/figures/report_luminance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace skylit {
namespace {

TEST(ReportLuminance, DecodesWithinTheStatedPrecisionOverSixteenDecades) {
  double worst = 0;
  for (double log10 = -5.99; log10 < 9.99; log10 += 0.0137) {  // steps that fall anywhere within codes
    const double value = std::pow(10.0, log10);
    const double back = luminance_from_code(luminance_code(value));
    worst = std::max(worst, std::abs(back - value) / value);
  }
  EXPECT_LT(worst, LuminanceCodeScale::kRelativePrecision);
  EXPECT_GT(worst, 0.5 * LuminanceCodeScale::kRelativePrecision);  // the bound is not loose
}

TEST(ReportLuminance, EndsAndNonFiniteValues) {
  EXPECT_EQ(luminance_code(0), 0);
  EXPECT_EQ(luminance_code(-3), 0);
  EXPECT_EQ(luminance_code(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(luminance_code(1e-7), 0);
  EXPECT_EQ(luminance_code(1e-6), 1);
  EXPECT_EQ(luminance_code(1e10), 65535);
  EXPECT_EQ(luminance_code(1e30), 65535);
  EXPECT_EQ(luminance_code(std::numeric_limits<double>::infinity()), 65535);
  EXPECT_EQ(luminance_from_code(0), 0);
  EXPECT_NEAR(luminance_from_code(65535), 1e10, 1e10 * 1e-9);
}

TEST(ReportLuminance, BytesAreLittleEndianPairs) {
  const std::vector<float> values{0.0f, 1.0f};
  const std::vector<uint8_t> bytes = luminance_code_bytes(values);
  ASSERT_EQ(bytes.size(), 4u);
  EXPECT_EQ(bytes[0] | (bytes[1] << 8), 0);
  EXPECT_EQ(bytes[2] | (bytes[3] << 8), luminance_code(1.0));
}

}  // namespace
}  // namespace skylit
