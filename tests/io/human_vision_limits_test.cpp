// Veiling glare and acuity in the human display (io/image/human_vision_limits.h): the
// acuity fit at its published levels, detail finer than it removed at night and kept
// by day, the veil of one source against a hand computation, and a lamp's veil
// brightening what lies next to it on the display.
#include "skylit/io/image/human_vision_limits.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/io/image/human_display.h"

namespace skylit {
namespace {

TEST(HumanVisionLimits, AcuityFitAtDayAndNightLevels) {
  // 17.25 atan(1.4 log₁₀ L + 0.35) + 25.72, by hand: at 100 cd/m² atan(3.15) = 1.263728,
  // 47.514 cycles/degree; at 0.001 cd/m² atan(−3.85) = −1.316701, 3.007.
  EXPECT_NEAR(acuity_cycles_per_degree(100), 47.514, 0.001);
  EXPECT_NEAR(acuity_cycles_per_degree(1e-3), 3.007, 0.001);
  EXPECT_LT(acuity_cycles_per_degree(1e-5), acuity_cycles_per_degree(1e-3));
}

// Vertical stripes one pixel wide, 1 and 0 cd/m² (grey), and the contrast between two
// neighbouring columns at the image's centre after acuity_limited.
double stripe_contrast_after(double adaptation, double degrees_per_pixel) {
  XyzImage image(32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) image.set(x, y, {0.95 * (x % 2), 1.0 * (x % 2), 1.09 * (x % 2)});
  const XyzImage out = acuity_limited(image, std::vector<double>(32 * 32, adaptation), degrees_per_pixel);
  return std::abs(out.at(16, 16).y - out.at(15, 16).y);
}

TEST(HumanVisionLimits, FineDetailLostAtNightKeptByDay) {
  // 0.1°/pixel: stripes of 5 cycles/degree. By day (47.5 c/°) they stay as they are; at
  // 0.001 cd/m² (3.0 c/°) one period is 3.3 pixels, a 3-pixel box: contrast 1/3; at
  // 10⁻⁵ cd/m² (1.2 c/°) 8.3 pixels, a 9-pixel box: 1/9.
  EXPECT_DOUBLE_EQ(stripe_contrast_after(100, 0.1), 1.0);
  EXPECT_NEAR(stripe_contrast_after(1e-3, 0.1), 1.0 / 3, 1e-6);
  EXPECT_NEAR(stripe_contrast_after(1e-5, 0.1), 1.0 / 9, 1e-6);
}

TEST(HumanVisionLimits, VeilOfOneSourceMatchesAHandComputation) {
  // Samples 1° apart in a row: a source L at the left, darkness elsewhere. At the right
  // end the source is 2° away and the dark middle sample 1°: weights cos θ / θ² (θ in
  // radians) of 820.2 and 3282.3, so the veil is 0.08 · L · 820.2 / 4102.5 = 0.015994 L.
  const std::vector<double> veil = veiling_luminance({1000.0, 0.0, 0.0}, 3, 1, 1.0);
  EXPECT_NEAR(veil[2], 15.994, 0.01);
  EXPECT_NEAR(veil[1], 0.08 * 1000 * 0.5, 0.01);  // the source and the dark end are equally far
  EXPECT_NEAR(veil[0], 0.0, 1e-12);               // the source's own sample gets the others' (dark) light
}

TEST(HumanVisionLimits, LampVeilsWhatStandsNextToIt) {
  // A dark street (0.01 cd/m², grey) with a lamp of 10⁵ cd/m² in its top-left corner,
  // 0.5° per pixel: on the human display a pixel 6 pixels (3°) from the lamp shows
  // brighter than one across the frame.
  XyzImage image(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double l = (x < 2 && y < 2) ? 1e5 : 0.01;
      image.set(x, y, {0.95047 * l, l, 1.08883 * l});
    }
  const std::vector<uint8_t> shown = human_display_srgb8(image, 0.5);
  const int near = shown[3 * (8 * 64 + 8)], far = shown[3 * (60 * 64 + 60)];
  EXPECT_GT(near, far + 10) << near << " " << far;
}

}  // namespace
}  // namespace skylit
