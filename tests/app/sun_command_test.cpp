// `skylit sun` as a user runs it: one JSON object that agrees with the library, a
// readable line without --json, and exit status 2 with one line for bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "../test_support.h"
#include "skylit/sun/solar_position.h"

namespace skylit {
namespace {

using testing::run_skylit;

// The NREL SPA paper's example site and instant (Reda & Andreas 2004, Table A5.1).
constexpr const char* kExample =
    "sun --lat 39.742476 --lon=-105.1786 --elevation 1830.14 --time 2003-10-17T12:30:30-07:00 "
    "--pressure 820 --temperature 11 --delta-t 67";

TEST(SunCommand, JsonIsOneObjectMatchingTheLibrary) {
  const auto r = run_skylit(std::string(kExample) + " --json");
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  ASSERT_TRUE(j.is_object());
  EXPECT_NEAR(j.at("zenith_deg").get<double>(), 50.11162, 1e-5);
  EXPECT_NEAR(j.at("azimuth_deg").get<double>(), 194.34024, 1e-5);
  EXPECT_NEAR(j.at("altitude_deg").get<double>(), 90.0 - 50.11162, 1e-5);
  EXPECT_NEAR(j.at("earth_sun_distance_au").get<double>(), 0.9965422974, 1e-8);
  EXPECT_NEAR(j.at("julian_day").get<double>(), 2452930.312847, 1e-6);
  EXPECT_DOUBLE_EQ(j.at("pressure_mbar").get<double>(), 820.0);

  // The defaults the program fills in are the library's.
  const auto d = run_skylit("sun --lat 35.68 --lon 139.69 --elevation 40 --time 2026-06-21T07:00:00+09:00 --json");
  ASSERT_EQ(d.exit_status, 0) << d.output;
  const nlohmann::json dj = nlohmann::json::parse(d.output);
  const SolarPosition sun =
      solar_position({35.68, 139.69, 40.0}, parse_offset_date_time("2026-06-21T07:00:00+09:00", "test"));
  EXPECT_NEAR(dj.at("altitude_deg").get<double>(), sun.altitude_deg, 1e-6);
  EXPECT_NEAR(dj.at("azimuth_deg").get<double>(), sun.azimuth_deg, 1e-6);
  EXPECT_NEAR(dj.at("zenith_deg").get<double>(), sun.zenith_deg, 1e-6);
  EXPECT_NEAR(dj.at("pressure_mbar").get<double>(), standard_pressure_mbar(40.0), 0.01);
}

TEST(SunCommand, WithoutJsonPrintsOneReadableLine) {
  const auto r = run_skylit(kExample);
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("altitude 39.888378"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("azimuth 194.34024"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("clockwise from north"), std::string::npos) << r.output;
}

TEST(SunCommand, BadValuesExitTwoWithOneLine) {
  const struct {
    const char* arguments;
    const char* message;
  } cases[] = {
      {"sun --lat 95 --lon 0 --time 2026-06-21T12:00:00Z", "--lat: expected a latitude"},
      {"sun --lat 45 --lon 190 --time 2026-06-21T12:00:00Z", "--lon: expected a longitude"},
      {"sun --lat 45 --lon 0 --time 2026-06-21T12:00:00", "--time: \"2026-06-21T12:00:00\" has no UTC offset"},
      {"sun --lat 45 --lon 0 --time 2026-02-29T12:00:00Z", "--time: 2026-02-29 is not a date"},
      {"sun --lat 45 --lon 0 --time noon", "--time: expected an ISO 8601 date-time"},
      {"sun --lat 45 --lon 0 --time 7000-01-01T00:00:00Z", "beyond the solar position algorithm's range"},
      {"sun --lat 45 --lon 0 --time 2026-06-21T12:00:00Z --pressure -5", "--pressure: expected"},
  };
  for (const auto& c : cases) {
    const auto r = run_skylit(std::string(c.arguments) + " --json");
    EXPECT_EQ(r.exit_status, 2) << c.arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.arguments << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.arguments << "\n" << r.output;
  }
  EXPECT_EQ(run_skylit("sun --lat 45 --time 2026-06-21T12:00:00Z").exit_status, 2);  // --lon missing
  EXPECT_EQ(run_skylit("sun --lat north --lon 0 --time 2026-06-21T12:00:00Z").exit_status, 2);
}

TEST(SunCommand, HelpStatesUnitsAndConventions) {
  const auto help = run_skylit("sun --help");
  EXPECT_EQ(help.exit_status, 0);
  for (const char* text : {"clockwise from north", "east positive", "north positive", "UTC offset", "mbar", "°C",
                           "refraction", "seconds", "metres"})
    EXPECT_NE(help.output.find(text), std::string::npos) << text << "\n" << help.output;
}

}  // namespace
}  // namespace skylit
