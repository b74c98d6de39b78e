// compare_region against numbers worked out by hand: means, B/A, the standard errors
// of the means (sqrt(Σ SE²) / N) and of the ratio (delta method), dark pixels left out
// of the per-pixel percentiles, and the type-7 quantile. Pixels are floats: values they
// hold exactly are compared to 1e-12, others to float precision.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../io/image_test_util.h"
#include "skylit/compare/region_comparison.h"

namespace skylit {
namespace {

using test::row_of_greys;

TEST(RegionComparison, MeansRatioAndStandardErrorsByHand) {
  const XyzImage a = row_of_greys({10, 10, 10, 10});
  const XyzImage b = row_of_greys({11, 13, 12, 12});
  const XyzImage se_a = row_of_greys({2, 2, 2, 2});
  const XyzImage se_b = row_of_greys({1, 1, 1, 1});
  const RegionComparison r = compare_region(whole_image_region(4, 1), a, b, {&se_a, &se_b});
  EXPECT_EQ(r.name, "all");
  EXPECT_EQ(r.pixels, 4);
  EXPECT_EQ(r.dark_pixels, 0);
  EXPECT_NEAR(r.mean_a_cd_m2, 10.0, 1e-12);
  EXPECT_NEAR(r.mean_b_cd_m2, 12.0, 1e-12);
  EXPECT_NEAR(r.ratio, 1.2, 1e-12);
  // sqrt(4 · 2²) / 4 = 1 and sqrt(4 · 1²) / 4 = 0.5.
  EXPECT_NEAR(*r.mean_a_standard_error_cd_m2, 1.0, 1e-12);
  EXPECT_NEAR(*r.mean_b_standard_error_cd_m2, 0.5, 1e-12);
  // sqrt(0.5² + 1.2² · 1²) / 10 = sqrt(1.69) / 10 = 0.13.
  EXPECT_NEAR(*r.ratio_standard_error, 0.13, 1e-12);
  // Per-pixel ratios 1.1, 1.2, 1.2, 1.3: median 1.2; p5 at rank 0.15 = 1.1 + 0.15 · 0.1.
  EXPECT_NEAR(r.pixel_ratio_median, 1.2, 1e-12);
  EXPECT_NEAR(r.pixel_ratio_p05, 1.115, 1e-12);
  EXPECT_NEAR(r.pixel_ratio_p95, 1.285, 1e-12);
}

TEST(RegionComparison, OneStandardErrorImageMeansTheOtherRenderHasNoNoise) {
  const XyzImage a = row_of_greys({10, 10});
  const XyzImage b = row_of_greys({5, 5});
  const XyzImage se_b = row_of_greys({0.3, 0.4});
  const RegionComparison r = compare_region(whole_image_region(2, 1), a, b, {nullptr, &se_b});
  EXPECT_NEAR(*r.mean_a_standard_error_cd_m2, 0.0, 1e-15);
  EXPECT_NEAR(*r.mean_b_standard_error_cd_m2, 0.25, 1e-7);  // sqrt(0.09 + 0.16) / 2
  EXPECT_NEAR(*r.ratio_standard_error, 0.025, 1e-8);        // 0.25 / 10
  const RegionComparison none = compare_region(whole_image_region(2, 1), a, b);
  EXPECT_FALSE(none.ratio_standard_error.has_value());
  EXPECT_FALSE(none.mean_a_standard_error_cd_m2.has_value());
}

TEST(RegionComparison, DarkPixelsCountInMeansButNotInPixelRatios) {
  const XyzImage a = row_of_greys({0, 4, 0});
  const XyzImage b = row_of_greys({0, 8, 3});
  const RegionComparison r = compare_region(rectangle_region("row", 3, 0, 0, 3, 1), a, b);
  EXPECT_EQ(r.pixels, 3);
  EXPECT_EQ(r.dark_pixels, 1);
  EXPECT_NEAR(r.ratio, (11.0 / 3) / (4.0 / 3), 1e-12);
  // Lit pixels: 8/4 = 2 and 3/δ = 3e4 (A dark, B lit): median halfway.
  EXPECT_NEAR(r.pixel_ratio_median, (2 + 3 / kDarkLuminance_cd_m2) / 2, 1e-6);
  EXPECT_DOUBLE_EQ(pixel_luminance_ratio(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(pixel_luminance_ratio(-1, 5e-5), 1.0);
}

TEST(RegionComparison, NoLitPixelGivesNoRatio) {
  const XyzImage black = row_of_greys({0, 0});
  const RegionComparison r = compare_region(whole_image_region(2, 1), black, black);
  EXPECT_TRUE(std::isnan(r.ratio));
  EXPECT_TRUE(std::isnan(r.pixel_ratio_median));
}

TEST(RegionComparison, NonFinitePixelsAreLeftOut) {
  XyzImage a = row_of_greys({10, 10});
  const XyzImage b = row_of_greys({20, 30});
  a.set(1, 0, {NAN, NAN, NAN});
  const RegionComparison r = compare_region(whole_image_region(2, 1), a, b);
  EXPECT_EQ(r.pixels, 1);
  EXPECT_NEAR(r.ratio, 2.0, 1e-12);
}

TEST(Quantile, LinearBetweenOrderStatistics) {
  std::vector<double> v = {4, 1, 3, 2};
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile(v, 0.05), 1.15);
  std::vector<double> one = {7};
  EXPECT_DOUBLE_EQ(quantile(one, 0.95), 7.0);
  std::vector<double> none;
  EXPECT_TRUE(std::isnan(quantile(none, 0.5)));
}

}  // namespace
}  // namespace skylit
