// The human-vision display (io/image/human_display.h): contrasts below the threshold-
// versus-intensity curve stay invisible on the display and contrasts well above it stay
// visible; a scotopic scene loses its colour and a photopic one keeps it.
#include "skylit/io/image/human_display.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skylit {
namespace {

TEST(HumanDisplay, ThresholdCurveIsContinuousAndWeberInDaylight) {
  // Eq. 8's pieces meet at their breakpoints (within 5 %: the paper's constants are
  // rounded; the largest step, 2.8 %, is 0.012 in log10, far below a visible change).
  for (double l : {-3.94, -1.44, -0.0184, 1.9}) {
    const double below = threshold_luminance(std::pow(10.0, l - 1e-9));
    const double above = threshold_luminance(std::pow(10.0, l + 1e-9));
    EXPECT_NEAR(below / above, 1.0, 0.05) << l;
  }
  // Photopic: Weber's law, ΔL/L = 10^−1.255 ≈ 5.6 %.
  EXPECT_NEAR(threshold_luminance(1000) / 1000, std::pow(10.0, -1.255), 1e-12);
  EXPECT_NEAR(threshold_luminance(1e-5), std::pow(10.0, -2.86), 1e-15);  // absolute threshold
}

TEST(HumanDisplay, StepsBelowThresholdStayInvisibleAndStepsWellAboveStayVisible) {
  // A scene spread evenly over 6 decades (0.01 … 10 000 cd/m²), more than the display's
  // 1.5: histogram adjustment compresses it. At adaptation levels through the mesopic
  // and photopic ranges, a world step of half the threshold must map to less than the
  // display's threshold at the displayed level, and a step of 10 thresholds to more.
  std::vector<double> samples;
  for (int i = 0; i < 6000; ++i) samples.push_back(std::pow(10.0, -2 + 6.0 * (i + 0.5) / 6000));
  const HumanDisplayMapping mapping(samples);
  for (double l : {0.05, 0.3, 2.0, 20.0, 300.0, 3000.0}) {
    const double t = threshold_luminance(l);
    const double d = mapping.display_luminance(l);
    const double display_threshold = threshold_luminance(d);
    EXPECT_LT(mapping.display_luminance(l + 0.5 * t) - d, display_threshold) << l;
    EXPECT_GT(mapping.display_luminance(l + 10 * t) - d, display_threshold) << l;
    EXPECT_GE(d, kHumanDisplayMin * 0.999);
    EXPECT_LE(d, kHumanDisplayMax * 1.001);
  }
  // Monotonic: brighter stays brighter.
  double previous = 0;
  for (double l = 0.01; l < 1e4; l *= 1.3) {
    EXPECT_GE(mapping.display_luminance(l), previous) << l;
    previous = mapping.display_luminance(l);
  }
}

// A uniform frame of a saturated red at luminance y, shown on the human display.
std::vector<uint8_t> red_frame(double y) {
  XyzImage image(16, 16);
  // sRGB red's chromaticity (0.64, 0.33): X = x/y·Y, Z = (1 − x − y)/y·Y.
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) image.set(i, j, {0.64 / 0.33 * y, y, 0.03 / 0.33 * y});
  return human_display_srgb8(image, 0.1);
}

TEST(HumanDisplay, ScotopicSceneLosesItsColour) {
  const std::vector<uint8_t> night = red_frame(1e-3);  // below 0.0056 cd/m²: rods only
  EXPECT_EQ(night[0], night[1]);
  EXPECT_EQ(night[1], night[2]);
  EXPECT_GT(night[0], 0);  // dim, but seen
  // Photopic: the red kept (as far as the display's gamut allows at that brightness).
  const std::vector<uint8_t> day = red_frame(100);
  EXPECT_GT(day[0], day[1] + 50);
  const std::vector<uint8_t> dusk = red_frame(0.18);  // mesopic: in between
  EXPECT_GT(dusk[0], dusk[1]);
  EXPECT_LT(dusk[0] - dusk[1], day[0] - day[1]);
  // A black frame is black, not NaN.
  EXPECT_EQ(human_display_srgb8(XyzImage(4, 4), 0.5)[0], 0);
}

}  // namespace
}  // namespace skylit
