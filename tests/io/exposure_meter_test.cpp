// Automatic exposure's meter (io/image/exposure_meter.h) against its definition computed
// by hand, and on the frames that must not fool or break it.
#include "skylit/io/image/exposure_meter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skylit/io/image/image.h"
#include "skylit/io/image/tone_map.h"

namespace skylit {
namespace {

TEST(ExposureMeter, LogAverageOverTheWindowBelowTheHighlights) {
  // 200 pixels: 98 at 1e-5 (a night sky, below the window), 100 at 1 and at 4 in equal
  // numbers, one lamp at 1e6 and one at 1e5. The 99th percentile (index 197 of 0…199)
  // is 4, so the window is [4e-3, 4]; the lamps count as 4.
  std::vector<float> y(98, 1e-5f);
  y.insert(y.end(), 50, 1.0f);
  y.insert(y.end(), 50, 4.0f);
  y.push_back(1e6f);
  y.push_back(1e5f);
  const double expected = std::exp((50 * std::log(1.0) + 52 * std::log(4.0)) / 102);
  EXPECT_NEAR(metered_luminance(y), expected, 1e-6 * expected);
}

TEST(ExposureMeter, SkipsNonFiniteAndFloorsDarkScenes) {
  const std::vector<float> with_nan{2.0f, NAN, INFINITY, 2.0f};
  EXPECT_NEAR(metered_luminance(with_nan), 2.0, 1e-6);
  // Uniformly dark (a moonless sky): the floor, so the frame shows dark, not grey.
  const std::vector<float> moonless(100, 4e-5f);
  EXPECT_EQ(metered_luminance(moonless), kDarkestMeteredLuminance);
  EXPECT_EQ(metered_luminance(std::vector<float>{}), kDarkestMeteredLuminance);
}

TEST(ExposureMeter, BlackFrameAndOneBrightPixelGiveAFiniteExposure) {
  XyzImage black(64, 32);
  XyzImage one_sun = black;
  one_sun.set(10, 10, {1e9, 1.6e9, 1e9});
  for (const XyzImage* image : {&black, &one_sun}) {
    const double ev = automatic_exposure_ev(*image);
    ASSERT_TRUE(std::isfinite(ev));
    // One pixel of 2048 is above the 99th percentile (0): metered as the floor.
    EXPECT_NEAR(ev, std::log2(kDarkestMeteredLuminance / (1.2 * kExposureKey)), 1e-12);
    const std::vector<uint8_t> srgb = display_srgb8(*image, {});
    EXPECT_EQ(srgb[0], 0);
  }
  EXPECT_EQ(display_srgb8(one_sun, {})[3 * (10 * 64 + 10)], 255);  // the sun itself: white
}

}  // namespace
}  // namespace skylit
