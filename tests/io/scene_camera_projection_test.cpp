// The camera block's projection keys and render.false_colour: read with their defaults
// and limits, and every misuse a one-line InputError that names the place.
#include <gtest/gtest.h>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit {
namespace {

using testing::TempDir;

Scene load_with(const std::vector<std::string>& overrides) {
  TempDir dir;
  return load_scene(dir.write("scene.json", testing::small_scene_json()), overrides);
}

std::string error_with(const std::vector<std::string>& overrides) {
  return testing::input_error_of([&] { load_with(overrides); });
}

TEST(SceneCameraProjection, ProjectionsReadWithTheirDefaults) {
  EXPECT_EQ(load_with({}).camera.projection, Projection::perspective);
  // A fisheye's vertical_fov_deg given in the file (60) is its circle's angle.
  Scene s = load_with({"camera.projection=fisheye_equisolid"});
  EXPECT_EQ(s.camera.projection, Projection::fisheye_equisolid);
  EXPECT_DOUBLE_EQ(s.camera.vertical_fov_deg, 60);
  s = load_with({"camera.projection=equirectangular", "camera.vertical_fov_deg=180", "camera.horizontal_fov_deg=270"});
  EXPECT_EQ(s.camera.projection, Projection::equirectangular);
  EXPECT_DOUBLE_EQ(s.camera.horizontal_fov_deg, 270);
  s = load_with({"camera.lens_shift=[0.1, 0.3]"});
  EXPECT_DOUBLE_EQ(s.camera.shift_x, 0.1);
  EXPECT_DOUBLE_EQ(s.camera.shift_y, 0.3);
}

TEST(SceneCameraProjection, MisusesAreNamed) {
  EXPECT_NE(error_with({"camera.projection=fisheye"}).find("camera.projection"), std::string::npos);
  EXPECT_NE(error_with({"camera.projection=cylindrical", "camera.lens_shift=[0, 0.2]"})
                .find("camera.lens_shift: lens_shift is for the perspective projection"),
            std::string::npos);
  EXPECT_NE(error_with({"camera.horizontal_fov_deg=90"}).find("camera.horizontal_fov_deg"), std::string::npos);
  EXPECT_NE(error_with({"camera.projection=fisheye_hemispherical", "camera.vertical_fov_deg=200"})
                .find("camera.vertical_fov_deg"),
            std::string::npos);
  EXPECT_NE(error_with({"camera.lens_shift=[0.1]"}).find("camera.lens_shift"), std::string::npos);
  EXPECT_NE(error_with({"camera.lens_shift=[0.1, 5]"}).find("camera.lens_shift"), std::string::npos);
}

TEST(SceneFalseColour, ReadWithLimits) {
  const Scene s = load_with({"render.false_colour={\"scale\": \"linear\", \"max\": 500, \"contours\": true}"});
  EXPECT_EQ(s.render.false_colour.scale, FalseColourScale::linear);
  EXPECT_EQ(s.render.false_colour.max, 500);
  EXPECT_TRUE(s.render.false_colour.contours);
  EXPECT_FALSE(s.render.false_colour.underlay);
  EXPECT_NE(error_with({"render.false_colour.decades=0"}).find("render.false_colour.decades"), std::string::npos);
  EXPECT_NE(error_with({"render.false_colour.scale=cubic"}).find("render.false_colour.scale"), std::string::npos);
  EXPECT_NE(error_with({"render.false_colour.max=-1"}).find("render.false_colour.max"), std::string::npos);
}

}  // namespace
}  // namespace skylit
