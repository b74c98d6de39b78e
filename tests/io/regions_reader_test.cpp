// Regions from a JSON file (pixel and fractional rectangles, every mistake located by
// file and JSON path) and from a PNG mask (one region per non-black colour).
#include <gtest/gtest.h>

#include <string>

#include "../test_support.h"
#include "skylit/figures/raster.h"
#include "skylit/io/regions/regions_reader.h"

namespace skylit {
namespace {

using testing::input_error_of;
using testing::TempDir;

TEST(RegionsFile, PixelAndFractionRectangles) {
  TempDir dir;
  const auto file = dir.write("regions.json", R"({"regions": [
    {"name": "sunlit wall", "rect": [1, 0, 3, 2]},
    {"name": "right half", "rect_fraction": [0.5, 0, 1, 1]}
  ]})");
  const auto regions = read_regions_file(file, 4, 3);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].name, "sunlit wall");
  EXPECT_EQ(regions[0].pixels, (std::vector<uint32_t>{1, 2, 5, 6}));
  EXPECT_EQ(regions[1].name, "right half");
  EXPECT_EQ(regions[1].pixels, (std::vector<uint32_t>{2, 3, 6, 7, 10, 11}));
}

TEST(RegionsFile, FractionsTakeThePixelsWhoseCentresLieInside) {
  TempDir dir;
  // Width 10: centres at 0.05, 0.15, ...; [0.1, 0.3) holds 0.15 and 0.25, i.e. pixels 1 and 2.
  const auto file = dir.write("r.json", R"({"regions": [{"name": "n", "rect_fraction": [0.1, 0, 0.3, 1]}]})");
  EXPECT_EQ(read_regions_file(file, 10, 1)[0].pixels, (std::vector<uint32_t>{1, 2}));
}

TEST(RegionsFile, MistakesNameTheFileAndThePlace) {
  TempDir dir;
  const auto error_of = [&](const std::string& text) {
    const auto file = dir.write("regions.json", text);
    return input_error_of([&] { read_regions_file(file, 4, 3); });
  };
  const std::string f = (dir.path() / "regions.json").string();
  EXPECT_EQ(
      error_of(R"({"regions": [{"name": "a", "rect": [0, 0, 1, 1]}, {"name": "b", "rect": [0, 0, 5, 1]}]})"),
      f + ": regions[1].rect: [0, 0, 5, 1] reaches outside the 4x3 images (x0, x1 from 0 to 4, y0, y1 from 0 to 3)");
  EXPECT_EQ(error_of(R"({"regions": [{"name": "a", "rect": [2, 0, 2, 1]}]})"),
            f + ": regions[0].rect: [2, 0, 2, 1] is empty; expected x0 < x1 and y0 < y1 (half-open pixel ranges)");
  EXPECT_NE(error_of(R"({"regions": [{"name": "a", "rect": [0, 0, 1.5, 1]}]})")
                .find("regions[0].rect[2]: expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"regions": [{"name": "a", "rect": [0, 0, 1, 1]}, {"name": "a", "rect": [0, 0, 1, 1]}]})")
                .find("regions[1].name: the name \"a\" is used twice"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"regions": [{"name": "a"}]})").find("regions[0]: expected exactly one of 'rect'"),
            std::string::npos);
  EXPECT_NE(
      error_of(R"({"regions": [{"name": "a", "rectangle": [0, 0, 1, 1]}]})").find("regions[0].rectangle: unknown key"),
      std::string::npos);
  EXPECT_NE(error_of(R"({"regions": [{"name": "a", "rect_fraction": [0, 0, 1.5, 1]}]})")
                .find("regions[0].rect_fraction[2]: expected a number from 0 to 1"),
            std::string::npos);
  EXPECT_NE(error_of("{\"regions\": [\n{]}").find("regions.json:2:2: invalid JSON"), std::string::npos);
  EXPECT_NE(error_of(R"({"regions": []})").find("regions: expected at least one region"), std::string::npos);
  EXPECT_EQ(input_error_of([&] { read_regions_file(dir.path() / "none.json", 4, 3); }),
            (dir.path() / "none.json").string() + ":1: cannot open the regions file: No such file or directory");
}

TEST(RegionMask, EachNonBlackColourIsARegionNamedByItsHex) {
  TempDir dir;
  Raster mask(4, 2, kBlack);
  set_pixel(mask, 0, 0, {255, 0, 0});
  set_pixel(mask, 1, 1, {255, 0, 0});
  set_pixel(mask, 3, 0, {0, 128, 255});
  write_png(mask, dir.path() / "mask.png");
  const auto regions = read_region_mask(dir.path() / "mask.png", 4, 2);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].name, "#0080ff");
  EXPECT_EQ(regions[0].pixels, (std::vector<uint32_t>{3}));
  EXPECT_EQ(regions[1].name, "#ff0000");
  EXPECT_EQ(regions[1].pixels, (std::vector<uint32_t>{0, 5}));
}

TEST(RegionMask, WrongSizeMissingFileAndAllBlackAreRefused) {
  TempDir dir;
  write_png(Raster(4, 2, kWhite), dir.path() / "mask.png");
  const std::string m = (dir.path() / "mask.png").string();
  EXPECT_EQ(input_error_of([&] { read_region_mask(dir.path() / "mask.png", 5, 2); }),
            "cannot read the mask \"" + m + "\": it is 4x2, the images are 5x2");
  EXPECT_NE(input_error_of([&] { read_region_mask(dir.path() / "none.png", 4, 2); }).find("none.png\": no such file"),
            std::string::npos);
  write_png(Raster(4, 2, kBlack), dir.path() / "black.png");
  EXPECT_NE(input_error_of([&] { read_region_mask(dir.path() / "black.png", 4, 2); }).find("no region"),
            std::string::npos);
}

}  // namespace
}  // namespace skylit
