// The scene file's `moon`, `night_sky` and `cars` (io/scene/night_reader.cpp,
// light_reader.cpp): one clear error naming the file and place for each mistake.
#include <gtest/gtest.h>

#include <string>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit {
namespace {

std::string load_error(const std::string& key, const std::string& value) {
  testing::TempDir dir;
  return testing::input_error_of([&] { load_scene(dir.write("night.json", testing::small_scene_with(key, value))); });
}

TEST(SceneNight, MistakesNameTheFileAndThePlace) {
  // The small scene gives the sun's position directly, not a site and a time.
  EXPECT_NE(load_error("moon", "true").find("night.json: moon:"), std::string::npos) << load_error("moon", "true");
  EXPECT_NE(load_error("moon", "\"sometimes\"").find("night.json: moon"), std::string::npos);
  EXPECT_NE(load_error("moon", "3").find("night.json: moon"), std::string::npos);
  EXPECT_NE(load_error("night_sky", R"({"artificial_zenith_cd_m2": -1})").find("artificial_zenith_cd_m2"),
            std::string::npos);
  EXPECT_NE(load_error("night_sky", R"({"stars": true})").find("stars"), std::string::npos);
  EXPECT_NE(load_error("cars", R"([{"position": [0, 0, 0], "heading_deg": 0, "beam": "dipped"}])").find("beam"),
            std::string::npos);
  EXPECT_NE(load_error("cars", R"([{"position": [0, 0, 0]}])").find("heading_deg"), std::string::npos);
  EXPECT_NE(load_error("cars", R"({"position": [0, 0, 0]})").find("an array of cars"), std::string::npos);
}

TEST(SceneNight, AutoLeavesTheSunByDayAndAMoonNeedsTheSunDown) {
  // A site and a noon time: "auto" keeps the sun; true is refused while the sun is up.
  testing::TempDir dir;
  std::string text = testing::small_scene_with("moon", "\"auto\"");
  const std::string sun = R"("sun": {"altitude_deg": 40, "azimuth_deg": 135},)";
  text.replace(text.find(sun), sun.size(),
               R"("site": {"latitude_deg": 52.37, "longitude_deg": 4.9}, "time": "2024-06-21T12:00:00+02:00",)");
  const Scene day = load_scene(dir.write("day.json", text));
  EXPECT_FALSE(day.atmosphere.moon.has_value());
  EXPECT_GT(day.sun.altitude_deg, 50);
  text.replace(text.find("\"auto\""), 6, "true");
  const std::string error = testing::input_error_of([&] { load_scene(dir.write("day.json", text)); });
  EXPECT_NE(error.find("below the horizon"), std::string::npos) << error;
}

}  // namespace
}  // namespace skylit
