// The report's conditions say what the renderer used: a CIE sky in place of the
// atmosphere's, and the weather file's record with what was made of it (an outside trial
// found an overcast weather hour described as the clear scattering atmosphere alone).
#include "skylit/io/scene/scene_conditions.h"

#include <gtest/gtest.h>

#include "../io/epw_fixture.h"
#include "skylit/io/weather/weather_conditions.h"

namespace skylit {
namespace {

std::string row(const std::vector<ConditionRow>& rows, const std::string& subject) {
  for (const ConditionRow& r : rows)
    if (r.subject == subject) return r.description;
  ADD_FAILURE() << "no row " << subject;
  return {};
}

TEST(SceneConditions, SayTheCieSkyAndTheWeatherRecordUsed) {
  Scene plain;
  EXPECT_NE(row(scene_conditions(plain), "Sky").find("from the atmosphere above"), std::string::npos);
  EXPECT_NE(row(scene_conditions(plain), "Weather").find("none"), std::string::npos);

  // An overcast hour: no beam with the sun up, 18,000 lx of diffuse light.
  testing::EpwRecordFields overcast;
  overcast.day = 26, overcast.dni = "0", overcast.dn_lux = "0", overcast.total_cover = "10",
  overcast.opaque_cover = "10";
  const EpwFile file = parse_epw(testing::epw_fixture({overcast}), "fixture.epw");
  Scene scene;
  apply_weather_hour(file, epw_hour_containing(file, 6, 26, 13, 0, "test"), scene);
  const std::vector<ConditionRow> rows = scene_conditions(scene);
  const std::string sky = row(rows, "Sky");
  EXPECT_NE(sky.find("CIE standard general sky type 1 (ISO 15469) scaled to 1.8e+04 lx"), std::string::npos) << sky;
  EXPECT_NE(sky.find("no direct sun"), std::string::npos) << sky;
  const std::string weather = row(rows, "Weather");
  EXPECT_NE(weather.find("fixture.epw"), std::string::npos) << weather;
  EXPECT_NE(weather.find("06-26 hour 13"), std::string::npos) << weather;
  EXPECT_NE(weather.find("sky: overcast"), std::string::npos) << weather;
}

}  // namespace
}  // namespace skylit
