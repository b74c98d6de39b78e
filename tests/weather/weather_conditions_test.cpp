// One EPW hour made into a scene (io/weather/weather_conditions.h): site and sun, the
// fitted aerosol, clouds, fog, snow, the overcast sky, and the model against the file.
#include "skylit/io/weather/weather_conditions.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "../io/epw_fixture.h"
#include "../test_support.h"
#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/optical_properties.h"
#include "skylit/io/scene/scene_report.h"
#include "skylit/spectrum/cie.h"
#include "skylit/sun/solar_position.h"

namespace skylit {
namespace {

using testing::epw_fixture;
using testing::EpwRecordFields;

Scene scene_for(const EpwFile& file, int month, int day, int hour) {
  Scene scene;
  apply_weather_hour(file, epw_hour_containing(file, month, day, hour, 0, "test"), scene);
  return scene;
}

TEST(WeatherConditions, PlacesTheSunAtTheHoursMiddleAndFitsTheBeam) {
  const EpwFile file = parse_epw(epw_fixture(), "fixture.epw");
  const Scene scene = scene_for(file, 6, 21, 13);
  // Hour 13 is 12:00–13:00 in the file's standard time, UTC−3:30: the sun at 12:30.
  SpaOptions air;
  air.pressure_mbar = 1013, air.temperature_c = 20;
  const SolarPosition sun =
      solar_position({48.5, -2.25, 812}, parse_offset_date_time("2001-06-21T12:30-03:30", "t"), air);
  EXPECT_NEAR(scene.sun.altitude_deg, sun.altitude_deg, 1e-9);
  EXPECT_NEAR(scene.sun.azimuth_deg, sun.azimuth_deg, 1e-9);
  EXPECT_DOUBLE_EQ(scene.atmosphere.site_elevation_m, 812);
  // The fitted aerosol gives the file's direct normal illuminance; the bisection stops
  // at 1e-6 in aod_550, far inside the issue's 2 %.
  const double beam = illuminance(direct_sun_at_ground(scene.atmosphere, radians(scene.sun.altitude_deg)));
  EXPECT_NEAR(beam, 70000, 0.001 * 70000);
  EXPECT_GT(scene.atmosphere.aerosol.aod_550, 0.0);
  EXPECT_FALSE(scene.cloud_layer);  // a clear sky
  EXPECT_FALSE(scene.fog);          // 30 km of visibility
  EXPECT_FALSE(scene.atmosphere.cie_sky);
  EXPECT_DOUBLE_EQ(scene.atmosphere.ground_albedo, 0.2);  // the file's albedo
  ASSERT_TRUE(scene.weather);
  EXPECT_NE(scene.weather->record.find("06-21 hour 13 (12:00-13:00"), std::string::npos) << scene.weather->record;
  EXPECT_EQ(scene.weather->sun_time, "2001-06-21T12:30-03:30");
}

TEST(WeatherConditions, CloudsFogSnowAndOvercastComeFromTheirFields) {
  EpwRecordFields cloudy;
  cloudy.day = 24, cloudy.opaque_cover = "6", cloudy.total_cover = "8", cloudy.visibility = "0.3",
  cloudy.snow_depth = "20", cloudy.ceiling = "77777";
  EpwRecordFields overcast;
  overcast.day = 25, overcast.dn_lux = "0", overcast.dni = "0", overcast.opaque_cover = "10",
  overcast.total_cover = "10", overcast.dh_lux = "21000";
  EpwRecordFields covered_night;  // a full cover with no sun: the densest generated layer
  covered_night.day = 26, covered_night.hour = 20, covered_night.opaque_cover = "10", covered_night.total_cover = "10";
  const EpwFile file = parse_epw(epw_fixture({cloudy, overcast, covered_night}), "fixture.epw");
  const Scene night = scene_for(file, 6, 26, 20);
  EXPECT_LT(night.sun.altitude_deg, 0.0);  // 19:30 at UTC−3:30, 2.25° W: solar 22:50
  ASSERT_TRUE(night.cloud_layer);
  EXPECT_DOUBLE_EQ(night.cloud_layer->coverage, 0.95);
  EXPECT_LE(expected_generated_cloud_count(*night.cloud_layer), static_cast<double>(kMaxGeneratedClouds));

  const Scene a = scene_for(file, 6, 24, 13);
  ASSERT_TRUE(a.cloud_layer);
  EXPECT_DOUBLE_EQ(a.cloud_layer->coverage, 0.6);                                // the opaque cover, not the total
  EXPECT_DOUBLE_EQ(a.cloud_layer->altitude, 2000.0);                             // an unlimited ceiling: the default
  EXPECT_EQ(a.cloud_layer->seed, scene_for(file, 6, 24, 13).cloud_layer->seed);  // reproducible
  EXPECT_LE(expected_generated_cloud_count(*a.cloud_layer), static_cast<double>(kMaxGeneratedClouds));
  ASSERT_TRUE(a.fog);
  EXPECT_DOUBLE_EQ(*a.fog->ground_visibility_m, 300.0);
  EXPECT_DOUBLE_EQ(a.atmosphere.ground_albedo, 0.6);  // snow

  const Scene b = scene_for(file, 6, 25, 13);
  ASSERT_TRUE(b.atmosphere.cie_sky);
  EXPECT_EQ(b.atmosphere.cie_sky->type, 1);
  EXPECT_FALSE(b.atmosphere.cie_sky->direct_sun);
  EXPECT_DOUBLE_EQ(b.atmosphere.cie_sky->diffuse_horizontal_lux, 21000.0);
  EXPECT_FALSE(b.cloud_layer);  // the CIE sky stands for the clouds
}

// The shared Amsterdam file's clear hours (no sky cover, a beam over 20,000 lx): the
// model's direct normal illuminance within 2 % of the file's (it is fitted) and the
// global horizontal within 10 % (its diffuse part is the model's own, unfitted).
// Two hours by default (each builds the sky's tables, about 2 s); all 102 with
// SKYLIT_EPW_ALL_CLEAR_HOURS=1, which today fails on eight hours whose global horizontal
// is +10.0 to +11.9 % (the model's diffuse light is brighter than the file's;
// docs/weather.md).
TEST(WeatherConditions, ClearHoursOfTheSharedFileMatchTheModel) {
  const std::filesystem::path path =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/NLD_Amsterdam062400_IWEC.epw";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path << " (the shared data is not on this machine)";
  const EpwFile file = read_epw(path);
  const bool all = std::getenv("SKYLIT_EPW_ALL_CLEAR_HOURS") != nullptr;
  int checked = 0;
  for (const EpwHour& h : file.hours) {
    const bool clear = h.opaque_sky_cover_tenths == 0.0 && h.total_sky_cover_tenths == 0.0 && h.direct_normal_lux &&
                       *h.direct_normal_lux > 20000 && h.global_horizontal_lux;
    if (!clear) continue;
    if (!all && !((h.month == 1 && h.day == 4 && h.hour == 12) || (h.month == 8 && h.day == 2 && h.hour == 12)))
      continue;
    Scene scene;
    apply_weather_hour(file, h, scene);
    check_weather_model(scene);
    const WeatherSummary& w = *scene.weather;
    EXPECT_NEAR(*w.model_direct_normal_lux, *h.direct_normal_lux, 0.02 * *h.direct_normal_lux) << w.record;
    EXPECT_NEAR(*w.model_global_horizontal_lux, *h.global_horizontal_lux, 0.10 * *h.global_horizontal_lux) << w.record;
    ++checked;
  }
  EXPECT_EQ(checked, all ? 102 : 2);
}

// A cloudy hour's beam is a mean through moving clouds: the aerosol comes from the
// visibility, and the beam says how much of the hour the sun shone (it is not the clear
// part of the sky). A beam brighter than that air lets through all hour means clearer air:
// then the aerosol is fitted to it with the sun out all hour.
TEST(WeatherConditions, ACloudyHoursBeamGivesTheSunshineNotTheAerosol) {
  EpwRecordFields dim, bright;
  dim.day = 24, dim.opaque_cover = dim.total_cover = "9", dim.dn_lux = "2800", dim.visibility = "20.0";
  bright.day = 25, bright.opaque_cover = bright.total_cover = "9", bright.dn_lux = "95000", bright.visibility = "5.0";
  const EpwFile file = parse_epw(epw_fixture({dim, bright}), "fixture.epw");
  const Scene a = scene_for(file, 6, 24, 13);
  AtmosphereSettings air = a.atmosphere;
  EXPECT_NEAR(air.aerosol.aod_550, aod_550_from_visibility(20.0, air.aerosol.scale_height_m), 1e-12);
  const double clear_beam = illuminance(direct_sun_at_ground(air, radians(a.sun.altitude_deg)));
  EXPECT_GT(clear_beam, 60000);  // a clear summer noon's beam, not 2800 / 0.1 = 28,000 lx
  EXPECT_NEAR(a.weather->clear_fraction, 2800 / clear_beam, 1e-9);
  const Scene b = scene_for(file, 6, 25, 13);
  EXPECT_DOUBLE_EQ(b.weather->clear_fraction, 1.0);
  air = b.atmosphere;
  EXPECT_LT(air.aerosol.aod_550, aod_550_from_visibility(5.0, air.aerosol.scale_height_m));
  EXPECT_NEAR(illuminance(direct_sun_at_ground(air, radians(b.sun.altitude_deg))), 95000, 0.001 * 95000);
}

// The outside check's hour (docs/weather.md, "Cloudy hours"): Amsterdam 07-10 hour 13,
// opaque cover 9/10, a beam of 2,800 lx and 43,100 lx of diffuse light. Its beam fitted
// as the clear tenth's (aod_550 1.22) and a layer of clouds each lit as if alone gave the
// clouded sky 65,800 lx (+53 %). Now the clouded sky, as the renderer sees it, gives the
// file's diffuse and global horizontal illuminance within 5 % (the clouds' light share is
// fitted to the diffuse light, and the beam is the file's), and the aerosol is the
// visibility's.
TEST(WeatherConditions, ANearlyOvercastHourGivesTheFilesDiffuseLight) {
  const std::filesystem::path path =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/NLD_Amsterdam062400_IWEC.epw";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path << " (the shared data is not on this machine)";
  const EpwFile file = read_epw(path);
  Scene scene = scene_for(file, 7, 10, 13);
  ASSERT_TRUE(scene.cloud_layer);
  EXPECT_DOUBLE_EQ(scene.cloud_layer->coverage, 0.9);
  EXPECT_LT(scene.atmosphere.aerosol.aod_550, 0.3);  // 45 km of visibility, not a haze of 1.2
  ASSERT_TRUE(scene.cloud_layer->diffuse_horizontal_lux);
  EXPECT_DOUBLE_EQ(*scene.cloud_layer->diffuse_horizontal_lux, 43100);
  check_weather_model(scene);
  const WeatherSummary& w = *scene.weather;
  EXPECT_NEAR(*w.model_diffuse_horizontal_lux, 43100, 0.05 * 43100);
  EXPECT_NEAR(*w.model_global_horizontal_lux, 45000, 0.05 * 45000);
  EXPECT_NEAR(*w.model_direct_normal_lux, 2800, 0.02 * 2800);
}

// A station's weather placed at a site elsewhere: the sun as seen from the site at the
// record's instant (the hour's middle in the file's standard time), the site's own
// elevation for the air, and how far the station lies.
TEST(WeatherConditions, TheSunStandsAsSeenFromTheSiteAtTheRecordsInstant) {
  const EpwFile file = parse_epw(epw_fixture(), "fixture.epw");
  Scene scene;
  const SiteLocation site{52.0, 4.37, 3};
  apply_weather_hour(file, epw_hour_containing(file, 6, 21, 13, 0, "test"), scene, site);
  SpaOptions air;
  air.pressure_mbar = 1013, air.temperature_c = 20;
  const SolarPosition sun = solar_position(site, parse_offset_date_time("2001-06-21T12:30-03:30", "t"), air);
  EXPECT_NEAR(scene.sun.altitude_deg, sun.altitude_deg, 1e-9);
  EXPECT_NEAR(scene.sun.azimuth_deg, sun.azimuth_deg, 1e-9);
  EXPECT_DOUBLE_EQ(scene.atmosphere.site_elevation_m, 3);
  ASSERT_TRUE(scene.site && scene.weather);
  EXPECT_EQ(scene.site->latitude_deg, 52.0);
  EXPECT_NEAR(scene.weather->station_distance_km, surface_distance_km(site, {48.5, -2.25, 0}), 1e-9);
  // Without a site the station is the site.
  EXPECT_EQ(scene_for(file, 6, 21, 13).weather->station_distance_km, 0);
}

// Opaque cover is part of the total: a record giving more of it than the total (a Long
// Beach file's 5 against 2) is said, and its opaque cover used.
TEST(WeatherConditions, OpaqueCoverBeyondTheTotalIsSaid) {
  EpwRecordFields odd;
  odd.day = 26, odd.total_cover = "2", odd.opaque_cover = "5";
  const EpwFile file = parse_epw(epw_fixture({odd}), "fixture.epw");
  const Scene scene = scene_for(file, 6, 26, 13);
  bool said = false;
  for (const std::string& d : scene.weather->decisions)
    said = said || d.find("the opaque cover (5 tenths) exceeds the total (2)") != std::string::npos;
  EXPECT_TRUE(said);
  bool consistent_said = false;
  const Scene consistent = scene_for(file, 6, 21, 13);
  for (const std::string& d : consistent.weather->decisions)
    consistent_said = consistent_said || d.find("exceeds the total") != std::string::npos;
  EXPECT_FALSE(consistent_said);
}

// A visibility beyond clean air's own (about 320 km at 550 nm), which files write for
// "unlimited" (999 km, TMYx's 777.7 and 1600 km), leaves the scene's aerosol (taken
// literally it gave none; a cut at 999 alone made 998 km aerosol-free and 999 hazy);
// 200 and 300 km give small ones, the clearer the less.
TEST(WeatherConditions, AnUnlimitedVisibilityLeavesTheAerosol) {
  EXPECT_NEAR(clean_air_visibility_km(), 320, 10);
  double previous_aod = 1;
  for (const auto& [visibility, unchanged] :
       {std::pair{"200.0", false}, std::pair{"300.0", false}, std::pair{"777.7", true}, std::pair{"998.0", true},
        std::pair{"999.0", true}, std::pair{"1600.0", true}}) {
    EpwRecordFields night;
    night.day = 26, night.hour = 1, night.visibility = visibility;
    night.ghi = night.dni = night.dhi = night.gh_lux = night.dn_lux = night.dh_lux = "0";
    const EpwFile file = parse_epw(epw_fixture({night}), "fixture.epw");
    Scene scene;
    scene.atmosphere.aerosol.aod_550 = 0.123;
    apply_weather_hour(file, epw_hour_containing(file, 6, 26, 1, 0, "test"), scene);
    if (unchanged) {
      EXPECT_EQ(scene.atmosphere.aerosol.aod_550, 0.123) << visibility;
    } else {
      EXPECT_GT(scene.atmosphere.aerosol.aod_550, 0.0001) << visibility;
      EXPECT_LT(scene.atmosphere.aerosol.aod_550, std::min(0.05, previous_aod)) << visibility;
      previous_aod = scene.atmosphere.aerosol.aod_550;
    }
  }
}

// A file that gives irradiances alone (PVGIS) with 0 W/m² in every field while the sun
// is up: no light, whatever the efficacy, so an overcast sky of 0 lx, not the scene's
// clear sky as for a missing value. (Such a record is not physical, a gap filled with
// zeros, and `skylit info` says so: SceneReport tests.)
TEST(WeatherConditions, ZeroIrradianceWithoutIlluminancesIsNoLightNotMissing) {
  // No illuminance in the whole file, so no efficacy of its own either.
  EpwRecordFields sunny, dark;
  sunny.gh_lux = sunny.dn_lux = sunny.dh_lux = "999999";  // missing
  dark = sunny;
  dark.day = 26;
  dark.ghi = dark.dni = dark.dhi = "0";
  const EpwFile file = parse_epw(testing::epw_header() + epw_record(sunny) + epw_record(dark), "fixture.epw");
  Scene scene;
  apply_weather_hour(file, epw_hour_containing(file, 6, 26, 13, 0, "test"), scene);
  ASSERT_TRUE(scene.weather.has_value());
  EXPECT_GT(scene.weather->sun_altitude_deg, 30);
  ASSERT_TRUE(scene.weather->file_global_horizontal_lux.has_value());
  EXPECT_EQ(*scene.weather->file_global_horizontal_lux, 0.0);
  ASSERT_TRUE(scene.atmosphere.cie_sky.has_value());
  EXPECT_EQ(scene.atmosphere.cie_sky->diffuse_horizontal_lux, 0.0);
  const auto said = [](const Scene& s) {
    for (const std::string& w : scene_warnings(s, false))
      if (w.find("gives no daylight (0 lx global horizontal) with the sun") != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(said(scene));
  // A sunlit record of the same file is not warned of.
  Scene lit;
  apply_weather_hour(file, epw_hour_containing(file, 6, 21, 13, 0, "test"), lit);
  EXPECT_FALSE(said(lit));
}

TEST(WeatherConditions, TheSceneFileTakesAnHourAndInfoReportsIt) {
  const testing::TempDir dir;
  dir.write("site.epw", epw_fixture());
  const std::string scene = R"({
  "camera": {"position": [0, -20, 2], "look_at": [0, 0, 3]},
  "weather": {"epw": "site.epw", "hour": "06-21T12:30"},
  "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
  "objects": [{"type": "plane", "material": "white", "size_m": 200}],
  "render": {"width": 8, "height": 6}
})";
  const auto file = dir.write("scene.json", scene);
  const testing::CommandResult info = testing::run_skylit("info " + testing::quoted(file));
  EXPECT_EQ(info.exit_status, 0) << info.output;
  EXPECT_NE(info.output.find("record 06-21 hour 13"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("direct normal: file 70000 lx, model 70000 lx"), std::string::npos) << info.output;

  // A malformed weather file: its own file, line and field, exit status 2.
  EpwRecordFields bad;
  bad.day = 26, bad.visibility = "far";
  dir.write("site.epw", epw_fixture({bad}));
  const testing::CommandResult broken = testing::run_skylit("info " + testing::quoted(file));
  EXPECT_EQ(broken.exit_status, 2);
  EXPECT_NE(broken.output.find("site.epw:13: field 25 (visibility): expected a number, found 'far'"), std::string::npos)
      << broken.output;
  // An hour the file does not hold, through render's --hour: refused before any output.
  dir.write("site.epw", epw_fixture());
  const testing::CommandResult missing = testing::run_skylit(
      "render " + testing::quoted(file) + " --hour 07-01T10:00 -q -o " + testing::quoted(dir.path() / "out.png"));
  EXPECT_EQ(missing.exit_status, 2);
  EXPECT_NE(missing.output.find("has no record for 07-01T10:00"), std::string::npos) << missing.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png"));
}

// A city model in a weather scene is placed around the scene's site, or its own centre;
// never around the weather station, which may lie hundreds of kilometres away (the
// fixture's is in Brittany, the example block in the Netherlands). A far station is
// said on stderr; the render still goes ahead.
TEST(WeatherConditions, ACityModelStaysWhereItIsAndAFarStationIsSaid) {
  const testing::TempDir dir;
  dir.write("site.epw", epw_fixture());
  const std::string model = "\"" + std::string(SKYLIT_SOURCE_DIR) + "/examples/models/city_block.city.json\"";
  auto scene_with = [&](const std::string& site) {
    return dir.write("scene.json", R"({
  "camera": {"position": [0, -80, 2], "look_at": [0, 0, 3]},
  "weather": {"epw": "site.epw", "hour": "06-21T12:30"},)" +
                                       site + R"(
  "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
  "objects": [{"type": "plane", "material": "white", "size_m": 200},
              {"name": "block", "type": "city", "file": )" +
                                       model + R"(}],
  "render": {"width": 8, "height": 6}
})");
  };
  const testing::CommandResult own = testing::run_skylit("info " + testing::quoted(scene_with("")));
  EXPECT_EQ(own.exit_status, 0) << own.output;
  EXPECT_NE(own.output.find("(the model's centre: no site given)"), std::string::npos) << own.output;
  EXPECT_NE(own.output.find("warning: weather: the file's station lies"), std::string::npos) << own.output;
  EXPECT_EQ(own.output.find("from the site:"), std::string::npos) << own.output;  // the block stands at the origin
  // A site beside the station: the block is placed around it, so it lies far from the
  // site (and is said to), and the station is near.
  const testing::CommandResult beside = testing::run_skylit(
      "info " + testing::quoted(scene_with(R"("site": {"latitude_deg": 48.55, "longitude_deg": -2.25},)")));
  EXPECT_EQ(beside.exit_status, 0) << beside.output;
  EXPECT_NE(beside.output.find("(the scene's site)"), std::string::npos) << beside.output;
  EXPECT_NE(beside.output.find("5.6 km from the site"), std::string::npos) << beside.output;
  EXPECT_EQ(beside.output.find("warning: weather:"), std::string::npos) << beside.output;
  EXPECT_NE(beside.output.find("warning: object 'block' lies"), std::string::npos) << beside.output;
  // The sun and time are still the weather file's alone.
  const testing::CommandResult both =
      testing::run_skylit("info " + testing::quoted(scene_with(R"("time": "2001-06-21T12:00+01:00",)")));
  EXPECT_EQ(both.exit_status, 2);
  EXPECT_NE(both.output.find("give either a weather file's hour or the time"), std::string::npos) << both.output;
}

}  // namespace
}  // namespace skylit
