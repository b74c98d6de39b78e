// `skylit compare` as a user runs it: per-region ratios and standard errors against
// hand-computed values (through --json), mask regions, the ratio map's colours, and
// mistakes that stop it with one line naming the file, exit status 2 and no output.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../io/image_test_util.h"
#include "../io/png_read_util.h"
#include "../test_support.h"
#include "skylit/figures/cool_warm.h"
#include "skylit/figures/ratio_map.h"

namespace skylit {
namespace {

using testing::quoted;
using testing::run_skylit;
using testing::TempDir;

// A `width` × 2 image of D65 greys: luminance by column (cd/m²), the same in both rows.
XyzImage columns_of_greys(const std::vector<double>& luminances) {
  XyzImage image(static_cast<int>(luminances.size()), 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double l = luminances[x];
      image.set(x, y, xyz_from_linear_srgb({l, l, l}));
    }
  return image;
}

// A: 10 cd/m² everywhere, standard error 2 per pixel. B: 12 on the left half, 5 on the
// right, standard error 1 per pixel. By hand, for each 2 × 2 half (N = 4):
//   SE of mean A = sqrt(4 · 2²) / 4 = 1, SE of mean B = sqrt(4 · 1²) / 4 = 0.5,
//   left:  B/A = 1.2, SE = sqrt(0.5² + 1.2² · 1²) / 10 = 0.13;
//   right: B/A = 0.5, SE = sqrt(0.5² + 0.5² · 1²) / 10 = 0.0707107.
struct Renders {
  TempDir dir;
  std::filesystem::path a = dir.path() / "a.exr", b = dir.path() / "b.pfm";
  std::filesystem::path se_a = dir.path() / "se_a.exr", se_b = dir.path() / "se_b.exr";
  Renders() {
    write_image(columns_of_greys({10, 10, 10, 10}), a);
    write_image(columns_of_greys({12, 12, 5, 5}), b);
    write_image(columns_of_greys({2, 2, 2, 2}), se_a);
    write_image(columns_of_greys({1, 1, 1, 1}), se_b);
  }
  std::string inputs() const {
    return quoted(a) + " " + quoted(b) + " --standard-error-a " + quoted(se_a) + " --standard-error-b " + quoted(se_b);
  }
};

TEST(CompareCommand, RegionRatiosAndStandardErrorsAsComputedByHand) {
  Renders r;
  const auto regions = r.dir.write("regions.json", R"({"regions": [
    {"name": "left half", "rect": [0, 0, 2, 2]},
    {"name": "right half", "rect_fraction": [0.5, 0, 1, 1]}]})");
  const auto json_path = r.dir.path() / "out.json";
  const auto result =
      run_skylit("compare " + r.inputs() + " --regions " + quoted(regions) + " --json " + quoted(json_path));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  const auto json = nlohmann::json::parse(testing::read_file(json_path));
  EXPECT_EQ(json["width"], 4);
  ASSERT_EQ(json["regions"].size(), 2u);
  const auto& left = json["regions"][0];
  EXPECT_EQ(left["name"], "left half");
  EXPECT_EQ(left["pixels"], 4);
  EXPECT_NEAR(left["mean_a_cd_m2"].get<double>(), 10.0, 1e-5);
  EXPECT_NEAR(left["mean_b_cd_m2"].get<double>(), 12.0, 1e-5);
  EXPECT_NEAR(left["mean_a_standard_error_cd_m2"].get<double>(), 1.0, 1e-6);
  EXPECT_NEAR(left["mean_b_standard_error_cd_m2"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(left["ratio"].get<double>(), 1.2, 1e-6);
  EXPECT_NEAR(left["ratio_standard_error"].get<double>(), 0.13, 1e-6);
  EXPECT_NEAR(left["pixel_ratio_median"].get<double>(), 1.2, 1e-6);
  const auto& right = json["regions"][1];
  EXPECT_EQ(right["pixels"], 4);
  EXPECT_NEAR(right["ratio"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(right["ratio_standard_error"].get<double>(), 0.0707107, 1e-6);
  EXPECT_NEAR(right["pixel_ratio_p95"].get<double>(), 0.5, 1e-6);
  // The table on stdout has one aligned row per region.
  EXPECT_NE(result.output.find("left half "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("1.2000"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("0.13"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("0.5000"), std::string::npos) << result.output;
}

TEST(CompareCommand, WithoutRegionsTheWholeImageIsOneAndNoStandardErrorIsShown) {
  Renders r;
  const auto json_path = r.dir.path() / "out.json";
  const auto result = run_skylit("compare " + quoted(r.a) + " " + quoted(r.b) + " --json " + quoted(json_path));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  const auto json = nlohmann::json::parse(testing::read_file(json_path));
  ASSERT_EQ(json["regions"].size(), 1u);
  EXPECT_EQ(json["regions"][0]["name"], "all");
  EXPECT_EQ(json["regions"][0]["pixels"], 8);
  EXPECT_NEAR(json["regions"][0]["ratio"].get<double>(), 0.85, 1e-6);  // (12 + 5) / 2 / 10
  EXPECT_TRUE(json["regions"][0]["ratio_standard_error"].is_null());
  EXPECT_NE(result.output.find("\nall "), std::string::npos) << result.output;
}

TEST(CompareCommand, MaskColoursAreRegions) {
  Renders r;
  Raster mask(4, 2, kBlack);
  set_pixel(mask, 0, 0, {255, 0, 0});
  set_pixel(mask, 1, 1, {255, 0, 0});
  set_pixel(mask, 3, 0, {0, 0, 255});
  write_png(mask, r.dir.path() / "mask.png");
  const auto json_path = r.dir.path() / "out.json";
  const auto result = run_skylit("compare " + r.inputs() + " --mask " + quoted(r.dir.path() / "mask.png") + " --json " +
                                 quoted(json_path));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  const auto json = nlohmann::json::parse(testing::read_file(json_path));
  ASSERT_EQ(json["regions"].size(), 2u);
  EXPECT_EQ(json["regions"][0]["name"], "#0000ff");
  EXPECT_EQ(json["regions"][0]["pixels"], 1);
  EXPECT_NEAR(json["regions"][0]["ratio"].get<double>(), 0.5, 1e-6);
  // One pixel: the standard errors are the pixel's own, SE = sqrt(1 + 0.25 · 4) / 10.
  EXPECT_NEAR(json["regions"][0]["ratio_standard_error"].get<double>(), std::sqrt(2.0) / 10, 1e-6);
  EXPECT_EQ(json["regions"][1]["name"], "#ff0000");
  EXPECT_EQ(json["regions"][1]["pixels"], 2);
  EXPECT_NEAR(json["regions"][1]["ratio"].get<double>(), 1.2, 1e-6);
}

TEST(CompareCommand, RatioMapShowsNeutralWhereEqualAndRedWhereTwiceAsBright) {
  TempDir dir;
  write_image(columns_of_greys({10, 10, 10, 0}), dir.path() / "a.exr");
  write_image(columns_of_greys({10, 20, 5, 0}), dir.path() / "b.exr");
  const auto map_path = dir.path() / "ratio.png";
  const auto result = run_skylit("compare " + quoted(dir.path() / "a.exr") + " " + quoted(dir.path() / "b.exr") +
                                 " -o " + quoted(map_path));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  const Raster map = test::read_png_raster(map_path);
  EXPECT_EQ(map.at(0, 1), kCoolWarmNeutral);
  EXPECT_EQ(map.at(1, 1), kCoolWarmRed);
  EXPECT_EQ(map.at(2, 1), kCoolWarmBlue);
  EXPECT_EQ(map.at(3, 1), kNoRatioGrey);
}

// Each mistake: exit status 2, one line naming `expected`, and the folder as it was.
void expect_refused(const TempDir& dir, const std::string& arguments, const std::string& expected) {
  const auto before = test::listing(dir.path());
  const auto result = run_skylit("compare " + arguments);
  EXPECT_EQ(result.exit_status, 2) << result.output;
  EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  EXPECT_EQ(test::listing(dir.path()), before) << arguments;
}

TEST(CompareCommand, MistakesExitTwoWithOneLineAndNoOutput) {
  Renders r;
  const auto d = r.dir.path();
  const std::string outputs = " -o " + quoted(d / "ratio.png") + " --json " + quoted(d / "out.json");
  write_image(columns_of_greys({1, 1, 1}), d / "small.exr");
  expect_refused(r.dir, quoted(r.a) + " " + quoted(d / "small.exr") + outputs,
                 (d / "small.exr").string() + " is 3x2 pixels but " + r.a.string() + " is 4x2");
  expect_refused(r.dir, quoted(r.a) + " " + quoted(d / "none.exr") + outputs,
                 "cannot read \"" + (d / "none.exr").string() + "\": no such file");
  expect_refused(r.dir, quoted(r.a) + " " + quoted(d / "b.tiff") + outputs, "unknown extension \".tiff\"");
  expect_refused(r.dir, quoted(r.a) + " " + quoted(r.b) + " --standard-error-b " + quoted(d / "small.exr") + outputs,
                 "small.exr is 3x2");
  const auto regions = r.dir.write("regions.json", R"({"regions": [{"name": "x", "rect": [0, 0, 9, 1]}]})");
  expect_refused(r.dir, r.inputs() + " --regions " + quoted(regions) + outputs,
                 regions.string() + ": regions[0].rect: [0, 0, 9, 1] reaches outside the 4x2 images");
  expect_refused(r.dir, r.inputs() + " -o " + quoted(d / "ratio.jpg"), "unknown extension \".jpg\"");
  expect_refused(r.dir, r.inputs() + " --json " + quoted(d / "no" / "out.json"), "does not exist");
}

}  // namespace
}  // namespace skylit
