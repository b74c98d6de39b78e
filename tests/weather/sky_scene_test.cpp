// The scene file's `sky` (docs/scene-format.md): a CIE sky's settings, and the mistakes
// a user can make with them, each one located error.
#include <gtest/gtest.h>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit {
namespace {

using testing::input_error_of;

std::string scene_with_sky(const std::string& sky) {
  std::string scene = testing::small_scene_json();
  scene.insert(scene.find("\"materials\""), "\"sky\": " + sky + ",\n  ");
  return scene;
}

TEST(SkyScene, ReadsACieSky) {
  const testing::TempDir dir;
  const Scene overcast =
      load_scene(dir.write("a.json", scene_with_sky(R"({"type": "cie_overcast", "diffuse_horizontal_lux": 9000})")));
  ASSERT_TRUE(overcast.atmosphere.cie_sky);
  EXPECT_EQ(overcast.atmosphere.cie_sky->type, 1);
  EXPECT_FALSE(overcast.atmosphere.cie_sky->direct_sun);  // types 1–6 hide the sun
  EXPECT_DOUBLE_EQ(overcast.atmosphere.cie_sky->diffuse_horizontal_lux, 9000);
  const Scene clear = load_scene(
      dir.write("b.json", scene_with_sky(R"({"type": "cie", "cie_type": 12, "diffuse_horizontal_lux": 15000})")));
  ASSERT_TRUE(clear.atmosphere.cie_sky);
  EXPECT_EQ(clear.atmosphere.cie_sky->type, 12);
  EXPECT_TRUE(clear.atmosphere.cie_sky->direct_sun);
  EXPECT_FALSE(load_scene(dir.write("c.json", scene_with_sky(R"({"type": "physical"})"))).atmosphere.cie_sky);
}

TEST(SkyScene, MistakesAreLocated) {
  const testing::TempDir dir;
  const auto error = [&](const std::string& sky) {
    return input_error_of([&] { load_scene(dir.write("s.json", scene_with_sky(sky))); });
  };
  EXPECT_NE(error(R"({"type": "cie", "cie_type": 16, "diffuse_horizontal_lux": 1})").find("sky.cie_type"),
            std::string::npos);
  EXPECT_NE(error(R"({"type": "cie", "cie_type": 3})").find("a CIE sky needs diffuse_horizontal_lux"),
            std::string::npos);
  EXPECT_NE(error(R"({"type": "physical", "cie_type": 3})").find("cie_type is for a CIE sky"), std::string::npos);
  EXPECT_NE(error(R"({"type": "cie_overcast", "cie_type": 3, "diffuse_horizontal_lux": 1})")
                .find("\"cie_overcast\" is CIE type 1"),
            std::string::npos);
  EXPECT_NE(error(R"({"type": "perez"})").find("sky.type"), std::string::npos);
}

}  // namespace
}  // namespace skylit
