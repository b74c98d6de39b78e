// Scene files' site, time and atmosphere: the sun placed by the NREL SPA from a site
// and a time, the air's settings, and the mistakes a user can make with them.
#include <gtest/gtest.h>

#include "../test_support.h"
#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/optical_properties.h"
#include "skylit/core/error.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/sun/solar_position.h"

namespace skylit {
namespace {

std::string scene_with(const std::string& sun_part, const std::string& extra = "") {
  std::string text = testing::small_scene_json();
  const std::string sun = "\"sun\": {\"altitude_deg\": 40, \"azimuth_deg\": 135},";
  text.replace(text.find(sun), sun.size(), sun_part + extra);
  return text;
}

std::string load_error(const std::string& text) {
  testing::TempDir dir;
  return testing::input_error_of([&] { load_scene(dir.write("scene.json", text)); });
}

TEST(SceneAtmosphere, SiteAndTimePlaceTheSun) {
  testing::TempDir dir;
  const Scene scene = load_scene(dir.write(
      "scene.json",
      scene_with(
          R"("site": {"latitude_deg": 34.39, "longitude_deg": 132.46, "elevation_m": 30}, "time": "2026-06-21T07:00:00+09:00",)")));
  SiteLocation site{34.39, 132.46, 30};
  const SolarPosition expected = solar_position(site, parse_offset_date_time("2026-06-21T07:00:00+09:00", "test"));
  EXPECT_DOUBLE_EQ(scene.sun.altitude_deg, expected.altitude_deg);
  EXPECT_DOUBLE_EQ(scene.sun.azimuth_deg, expected.azimuth_deg);
  // Hiroshima, 7 a.m. at the June solstice: the sun is low in the east-north-east.
  EXPECT_GT(scene.sun.altitude_deg, 15);
  EXPECT_LT(scene.sun.altitude_deg, 35);
  EXPECT_GT(scene.sun.azimuth_deg, 60);
  EXPECT_LT(scene.sun.azimuth_deg, 90);
  EXPECT_DOUBLE_EQ(scene.atmosphere.site_elevation_m, 30);
  EXPECT_NEAR(scene.atmosphere.earth_sun_distance_au, 1.0163, 0.0005);  // near aphelion
}

TEST(SceneAtmosphere, AtmosphereSettingsAreRead) {
  testing::TempDir dir;
  const Scene scene = load_scene(dir.write(
      "scene.json", testing::small_scene_json().replace(
                        1, 0,
                        R"( "atmosphere": {"model": "paper", "aod_550": 0.3, "angstrom_exponent": 1.0, "ozone_du": 250,
          "ground_albedo": 0.3, "aerosol_phase": "henyey_greenstein", "asymmetry": 0.7,
          "multiple_scattering": "hillaire", "air_density": "exponential", "refraction": false},)")));
  EXPECT_EQ(scene.atmosphere.model, AtmosphereModel::paper);
  EXPECT_FALSE(scene.atmosphere.refraction);
  EXPECT_EQ(scene.atmosphere.multiple_scattering, MultipleScatteringMethod::hillaire);
  EXPECT_EQ(scene.atmosphere.air_density, AirDensity::exponential);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.aod_550, 0.3);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.angstrom_exponent, 1.0);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.angstrom_exponent_short, 1.0);
  EXPECT_DOUBLE_EQ(scene.atmosphere.ozone_column_du, 250);
  EXPECT_DOUBLE_EQ(scene.atmosphere.ground_albedo, 0.3);
  EXPECT_EQ(scene.atmosphere.aerosol.phase, AerosolPhase::henyey_greenstein);
}

TEST(SceneAtmosphere, AerosolTypeSetsOpticalPropertiesNotTheAmount) {
  testing::TempDir dir;
  const Scene scene = load_scene(dir.write(
      "scene.json", testing::small_scene_json().replace(
                        1, 0, R"( "atmosphere": {"aerosol_type": "desert", "aod_550": 0.4, "asymmetry": 0.65},)")));
  const AerosolSettings desert = with_aerosol_type({}, AerosolType::desert);
  EXPECT_EQ(scene.atmosphere.aerosol.type, AerosolType::desert);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.aod_550, 0.4);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.single_scattering_albedo, desert.single_scattering_albedo);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.angstrom_exponent, desert.angstrom_exponent);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.asymmetry, 0.65);  // an explicit value wins over the type's
  const std::string error =
      load_error(testing::small_scene_json().replace(1, 0, R"( "atmosphere": {"aerosol_type": "volcanic"},)"));
  EXPECT_NE(error.find("atmosphere.aerosol_type"), std::string::npos) << error;
  EXPECT_NE(error.find("continental_average"), std::string::npos) << error;
}

TEST(SceneAtmosphere, VisibilityBecomesAnOpticalDepth) {
  testing::TempDir dir;
  const Scene scene = load_scene(
      dir.write("scene.json", testing::small_scene_json().replace(1, 0, R"( "atmosphere": {"visibility_km": 10},)")));
  // Koschmieder: 3.912/10 km = 3.912e-4 m⁻¹ at the ground, less Rayleigh (1.2e-5), over 1.2 km.
  EXPECT_NEAR(scene.atmosphere.aerosol.aod_550, (3.912e-4 - 0.0971 / 7994) * 1200, 0.002);
  EXPECT_DOUBLE_EQ(scene.atmosphere.aerosol.aod_550, aod_550_from_visibility(10, 1200));
}

TEST(SceneAtmosphere, MistakesAreNamed) {
  EXPECT_NE(load_error(scene_with(R"("time": "2026-06-21T07:00:00Z",)")).find("time: a time needs a site"),
            std::string::npos);
  EXPECT_NE(
      load_error(
          scene_with(
              R"("sun": {"altitude_deg": 4, "azimuth_deg": 90}, "site": {"latitude_deg": 0, "longitude_deg": 0}, "time": "2026-06-21T07:00:00Z",)"))
          .find("sun: give either the sun's position or a site and a time"),
      std::string::npos);
  const std::string no_offset =
      load_error(scene_with(R"("site": {"latitude_deg": 0, "longitude_deg": 0}, "time": "2026-06-21T07:00:00",)"));
  EXPECT_NE(no_offset.find("scene.json: time"), std::string::npos) << no_offset;
  EXPECT_NE(no_offset.find("UTC offset"), std::string::npos) << no_offset;
  EXPECT_NE(
      load_error(scene_with(R"("site": {"latitude_deg": 95, "longitude_deg": 0}, "time": "2026-06-21T07:00:00Z",)"))
          .find("site.latitude_deg: expected a number from -90 to 90"),
      std::string::npos);
  EXPECT_NE(
      load_error(testing::small_scene_json().replace(1, 0, R"( "atmosphere": {"aod_550": 0.2, "visibility_km": 5},)"))
          .find("atmosphere: give one of aod_550, visibility_km, linke_turbidity"),
      std::string::npos);
  EXPECT_NE(load_error(testing::small_scene_json().replace(1, 0, R"( "atmosphere": {"model": "klassen"},)"))
                .find("atmosphere.model: expected one of: full, paper"),
            std::string::npos);
  const std::string refraction =
      load_error(testing::small_scene_json().replace(1, 0, R"( "atmosphere": {"refraction": "on"},)"));
  EXPECT_NE(refraction.find("scene.json"), std::string::npos) << refraction;
  EXPECT_NE(refraction.find("atmosphere.refraction"), std::string::npos) << refraction;
  EXPECT_NE(refraction.find("true or false"), std::string::npos) << refraction;
}

}  // namespace
}  // namespace skylit
