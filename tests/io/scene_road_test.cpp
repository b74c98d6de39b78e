// The scene file's `lamp_rows` and `road_lighting` (io/scene/light_reader.cpp,
// road_lighting_reader.cpp) and `skylit road`: what a valid block gives, one clear error
// per mistake, and the program's exit status.
#include <gtest/gtest.h>

#include <string>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit {
namespace {

using testing::TempDir;

std::string with(const std::string& key, const std::string& value) { return testing::small_scene_with(key, value); }

constexpr const char* kRow = R"([{"name": "main", "centre_line": [[0, 0, 0], [0, 90, 0]], "road_width_m": 7,
    "spacing_m": 30, "height_m": 8, "overhang_m": 1, "arrangement": "opposite", "shape": "isotropic",
    "candela": 1000, "lamp": "led"}])";

TEST(SceneRoad, LampRowsBecomeNamedLights) {
  TempDir dir;
  const Scene scene = load_scene(dir.write("scene.json", with("lamp_rows", kRow)));
  ASSERT_EQ(scene.lights.size(), 8u);  // 0, 30, 60, 90 m, both sides
  EXPECT_EQ(scene.lights[0].name, "main 1");
  EXPECT_NEAR(scene.lights[1].luminaire.position().x, -2.5, 1e-12);
  EXPECT_NEAR(scene.lights[7].luminaire.position().y, 90, 1e-12);
}

TEST(SceneRoad, MistakesNameTheirPlace) {
  TempDir dir;
  struct Case {
    std::string key, value, expected;
  };
  const Case cases[] = {
      {"lamp_rows", R"([{"centre_line": [[0, 0, 0]], "road_width_m": 7, "spacing_m": 30, "height_m": 8,
        "shape": "isotropic", "candela": 1, "lamp": "led"}])",
       "lamp_rows[0].centre_line: expected an array of at least two points"},
      {"lamp_rows", R"([{"centre_line": [[0, 0, 0], [0, 0, 0]], "road_width_m": 7, "spacing_m": 30,
        "height_m": 8, "shape": "isotropic", "candela": 1, "lamp": "led"}])",
       "lamp_rows[0]: a lamp row's centre line has no length"},
      {"lamp_rows", R"([{"centre_line": [[0, 0, 0], [0, 9, 0]], "road_width_m": 7, "spacing_m": 0,
        "height_m": 8, "shape": "isotropic", "candela": 1, "lamp": "led"}])",
       "lamp_rows[0].spacing_m: expected a number from 0.5 to 10000"},
      {"lamp_rows", R"([{"centre_line": [[0, 0, 0], [0, 9, 0]], "road_width_m": 7, "spacing_m": 3,
        "height_m": 8, "arrangement": "zigzag", "shape": "isotropic", "candela": 1, "lamp": "led"}])",
       "lamp_rows[0].arrangement: expected one of: single_sided, opposite, staggered"},
      {"lamp_rows", R"([{"centre_line": [[0, 0, 0], [0, 9000000, 0]], "road_width_m": 7, "spacing_m": 1,
        "height_m": 8, "shape": "isotropic", "candela": 1, "lamp": "led"}])",
       "lamp_rows[0]: a lamp row would hold more than 100000 luminaires"},
      {"road_lighting", R"({"start": [0, 0, 0], "direction_deg": 0, "field_length_m": 30, "width_m": 7,
        "r_table": "R9"})",
       "road_lighting.r_table: unknown r-table 'R9'"},
      {"road_lighting", R"({"start": [0, 0, 0], "direction_deg": 0, "field_length_m": 30, "width_m": 7,
        "r_table": "R3", "lanes": 0})",
       "road_lighting.lanes: expected an integer from 1 to 12"},
  };
  for (const Case& c : cases) {
    const std::string message =
        testing::input_error_of([&] { load_scene(dir.write("scene.json", with(c.key, c.value))); });
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.value << "\n  gave: " << message;
  }
}

TEST(SceneRoad, RoadCommandPrintsTheFiguresOrOneErrorLine) {
  TempDir dir;
  std::string text = with("lamp_rows", kRow);
  text.insert(text.rfind('}'), R"(, "road_lighting": {"start": [0, 0, 0], "direction_deg": 0, "field_length_m": 30,
      "width_m": 7, "r_table": "R3"})");
  const auto good = testing::run_skylit("road " + testing::quoted(dir.write("road.json", text)) + " --json");
  EXPECT_EQ(good.exit_status, 0) << good.output;
  EXPECT_NE(good.output.find("\"average_luminance_cd_m2\": "), std::string::npos) << good.output;
  const auto missing = testing::run_skylit("road " + testing::quoted(dir.write("plain.json", with("lamp_rows", kRow))));
  EXPECT_EQ(missing.exit_status, 2);
  EXPECT_NE(missing.output.find("no road_lighting block"), std::string::npos) << missing.output;
  const auto none = testing::run_skylit("road " + testing::quoted(dir.write("road.json", text)) + " --lights 'car*'");
  EXPECT_EQ(none.exit_status, 2);
  EXPECT_NE(none.output.find("match --lights 'car*'"), std::string::npos) << none.output;
}

}  // namespace
}  // namespace skylit
