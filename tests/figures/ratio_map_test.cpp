// The ratio map: ratio 1 is the cool-warm map's neutral grey, 2 and beyond its red end,
// 1/2 and below its blue end, pixels dark in both renders the darker flat grey; the
// legend lies below the image; the PNG reads back with the same pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../io/image_test_util.h"
#include "../io/png_read_util.h"
#include "skylit/core/error.h"
#include "skylit/figures/cool_warm.h"
#include "skylit/figures/ratio_map.h"

namespace skylit {
namespace {

using test::row_of_greys;

TEST(CoolWarm, EndsAndMiddleAreMorelandsTable) {
  EXPECT_EQ(cool_warm(0.0), kCoolWarmBlue);
  EXPECT_EQ(cool_warm(0.5), kCoolWarmNeutral);
  EXPECT_EQ(cool_warm(1.0), kCoolWarmRed);
  EXPECT_EQ(cool_warm(-3.0), kCoolWarmBlue);
  EXPECT_EQ(cool_warm(1.0 / 32), (Rgb8{68, 90, 204}));
  EXPECT_EQ(cool_warm(1.5 / 32), (Rgb8{73, 97, 210}));  // halfway between entries 1 and 2, rounded
}

TEST(RatioMap, ColoursByRatioOnALogScale) {
  EXPECT_EQ(ratio_colour(1.0), kCoolWarmNeutral);
  EXPECT_EQ(ratio_colour(2.0), kCoolWarmRed);
  EXPECT_EQ(ratio_colour(5.0), kCoolWarmRed);
  EXPECT_EQ(ratio_colour(0.5), kCoolWarmBlue);
  EXPECT_EQ(ratio_colour(0.0), kCoolWarmBlue);
  EXPECT_EQ(ratio_colour(std::sqrt(2.0)), cool_warm(0.75));
}

TEST(RatioMap, PixelsAndLegend) {
  const XyzImage a = row_of_greys({10, 10, 10, 0, 10});
  const XyzImage b = row_of_greys({10, 20, 5, 0, 10.5});
  test::ScratchFolder dir("ratio_map");
  write_ratio_map(a, b, dir / "ratio.png");
  const Raster map = test::read_png_raster(dir / "ratio.png");
  EXPECT_EQ(map.at(0, 0), kCoolWarmNeutral);
  EXPECT_EQ(map.at(1, 0), kCoolWarmRed);
  EXPECT_EQ(map.at(2, 0), kCoolWarmBlue);
  EXPECT_EQ(map.at(3, 0), kNoRatioGrey);
  EXPECT_EQ(map.at(4, 0), ratio_colour(1.05));
  EXPECT_NE(ratio_colour(1.05), kCoolWarmNeutral);  // 5 % shows
  // The legend widens the raster and holds the whole colour scale below the image.
  EXPECT_GT(map.width, 200);
  EXPECT_GT(map.height, 40);
  EXPECT_EQ(map.at(10, 0), kWhite);
  bool has_red = false, has_blue = false;
  for (int y = 1; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      has_red = has_red || map.at(x, y) == kCoolWarmRed || map.at(x, y) == cool_warm(0.998);
      has_blue = has_blue || map.at(x, y) == kCoolWarmBlue || map.at(x, y) == cool_warm(0.002);
    }
  EXPECT_TRUE(has_red);
  EXPECT_TRUE(has_blue);
}

TEST(RatioMap, RefusesOtherExtensionsBeforeWriting) {
  test::ScratchFolder dir("ratio_map_errors");
  const XyzImage a = row_of_greys({1});
  EXPECT_THROW(write_ratio_map(a, a, dir / "ratio.exr"), InputError);
  EXPECT_THROW(write_ratio_map(a, a, dir / "missing" / "ratio.png"), InputError);
  EXPECT_TRUE(test::listing(dir.path()).empty());
}

}  // namespace
}  // namespace skylit
