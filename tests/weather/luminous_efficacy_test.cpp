// Perez et al. (1990)'s luminous efficacies (io/weather/luminous_efficacy.h): the laws
// against a hand computation, and, in a weather file that gives irradiances without
// illuminances, the illuminances they give against the shared Amsterdam file's own.
#include "skylit/io/weather/luminous_efficacy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "../io/epw_fixture.h"
#include "skylit/atmosphere/atmosphere.h"
#include "skylit/io/weather/weather_conditions.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// DNI 700, DHI 100 W m⁻², the sun 30° from the zenith, W = 2 cm, 1367 W m⁻²: worked by
// hand from the paper's equations and Table 4. ε = (8 + 1.041·z³)/(1 + 1.041·z³) =
// 7.090 (z = π/6; the last range, ε ≥ 6.2); m = 1.15399 (Kasten and Young 1989);
// Δ = 100·m/1367 = 0.084418, ln Δ = −2.47202. Global 99.65 + 1.86·2 − 4.46·cos z −
// 3.15·ln Δ = 107.294; direct 101.18 + 1.58·2 − 1.10·e^(5.73·z − 5) − 8.29·Δ = 103.491;
// diffuse 152.23 + 0.35·2 − 45.27·cos z − 7.98·ln Δ = 133.452 lm/W.
TEST(LuminousEfficacy, MatchesAHandComputationOfPerezsLaws) {
  const std::optional<DaylightEfficacy> e = perez_daylight_efficacy(700, 100, 30, 2, 1367);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->clearness, 7.0900, 1e-3);
  EXPECT_NEAR(e->brightness, 0.084418, 1e-5);
  EXPECT_NEAR(e->global_lm_w, 107.294, 0.01);
  EXPECT_NEAR(e->direct_lm_w, 103.491, 0.01);
  EXPECT_NEAR(e->diffuse_lm_w, 133.452, 0.01);
  // An overcast hour falls in the first range: no beam, ε = 1.
  const std::optional<DaylightEfficacy> overcast = perez_daylight_efficacy(0, 100, 60, 2, 1367);
  ASSERT_TRUE(overcast);
  EXPECT_DOUBLE_EQ(overcast->clearness, 1.0);
  EXPECT_GT(overcast->diffuse_lm_w, 90);
  EXPECT_LT(overcast->diffuse_lm_w, 140);
  // No sky to describe: the sun down, or no diffuse light.
  EXPECT_FALSE(perez_daylight_efficacy(700, 100, 95, 2, 1367));
  EXPECT_FALSE(perez_daylight_efficacy(700, 0, 30, 2, 1367));
}

// Whatever a file holds (the reader keeps values within the EPW dictionary's ranges;
// wider here), the efficacies are finite and not negative.
TEST(LuminousEfficacy, FiniteAndNotNegativeForExtremeSkies) {
  int skies = 0;
  for (const double direct : {0.0, 1e-9, 1.0, 800.0, 1500.0, 1e6})
    for (const double diffuse : {1e-9, 1.0, 100.0, 1500.0, 1e6})
      for (const double zenith : {0.0, 45.0, 89.99})
        for (const double water : {0.0, 2.0, 100.0}) {
          const std::optional<DaylightEfficacy> e = perez_daylight_efficacy(direct, diffuse, zenith, water, 1367);
          ASSERT_TRUE(e);
          for (const double v : {e->global_lm_w, e->direct_lm_w, e->diffuse_lm_w, e->clearness, e->brightness}) {
            EXPECT_TRUE(std::isfinite(v) && v >= 0) << direct << " " << diffuse << " " << zenith << " " << water;
          }
          ++skies;
        }
  EXPECT_EQ(skies, 270);
}

// The shared Amsterdam file (IWEC) gives both irradiances and illuminances. With its
// illuminances taken out, every ninth hour with a beam and a sky over 50 W m⁻² and the
// sun above 10° has its illuminances from its irradiances by Perez's efficacies, against
// the file's own. Those come from another computation (the IWEC set's) and Perez's
// efficacies are statistical fits with hour-to-hour scatter, so the bounds are the
// agreement to expect of such a model, not margins around today's values: medians of
// the ratios within 10 % (direct, diffuse) and 3 % (global), nine hours in ten within
// 20 %, 15 % and 5 %. Measured (every third hour, 573): medians 1.074, 0.946 and 0.986;
// the ninetieth percentiles of |ratio − 1| 15.3 %, 10.3 % and 2.9 %. The file splits its
// light between beam and sky a little differently; the global light agrees best.
TEST(LuminousEfficacy, AFileWithoutIlluminancesGetsTheSharedFilesOwnFromItsIrradiances) {
  const std::filesystem::path path =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/NLD_Amsterdam062400_IWEC.epw";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path << " (the shared data is not on this machine)";
  const EpwFile file = read_epw(path);
  EpwFile without = file;
  for (EpwHour& h : without.hours) h.global_horizontal_lux = h.direct_normal_lux = h.diffuse_horizontal_lux = {};
  std::vector<double> direct, diffuse, global;
  for (size_t i = 0; i < file.hours.size(); i += 9) {
    const EpwHour& h = file.hours[i];
    if (!h.direct_normal_w_m2 || !h.diffuse_horizontal_w_m2 || !h.global_horizontal_w_m2 || !h.direct_normal_lux ||
        !h.diffuse_horizontal_lux || !h.global_horizontal_lux || *h.direct_normal_w_m2 < 50 ||
        *h.diffuse_horizontal_w_m2 < 50)
      continue;
    Scene scene;
    apply_weather_hour(without, without.hours[i], scene);
    if (scene.sun.altitude_deg < 10) continue;
    const WeatherSummary& w = *scene.weather;
    ASSERT_TRUE(w.file_direct_normal_lux && w.file_diffuse_horizontal_lux && w.file_global_horizontal_lux) << w.record;
    direct.push_back(*w.file_direct_normal_lux / *h.direct_normal_lux);
    diffuse.push_back(*w.file_diffuse_horizontal_lux / *h.diffuse_horizontal_lux);
    global.push_back(*w.file_global_horizontal_lux / *h.global_horizontal_lux);
  }
  ASSERT_GT(direct.size(), 150u);
  auto check = [](std::vector<double> ratios, double median_bound, double p90_bound, const char* what) {
    std::sort(ratios.begin(), ratios.end());
    const double median = ratios[ratios.size() / 2];
    std::vector<double> off;
    for (const double r : ratios) off.push_back(std::abs(r - 1));
    std::sort(off.begin(), off.end());
    const double p90 = off[off.size() * 9 / 10];
    std::printf("%s: %zu hours, median ratio %.4f, 90th percentile of |ratio - 1| %.4f\n", what, ratios.size(), median,
                p90);
    EXPECT_NEAR(median, 1.0, median_bound) << what;
    EXPECT_LT(p90, p90_bound) << what;
  };
  check(direct, 0.10, 0.20, "direct normal");
  check(diffuse, 0.10, 0.15, "diffuse horizontal");
  check(global, 0.03, 0.05, "global horizontal");
}

// A file of irradiances alone (as PVGIS writes them: 999999 for every illuminance) was
// read as having no beam and no sky: its hours kept the scene's own clear air whatever
// the weather. Now the beam the aerosol is fitted to is the direct normal irradiance
// times Perez's direct efficacy for that hour, and `skylit info` says so.
TEST(LuminousEfficacy, AFileOfIrradiancesAloneFitsTheAirToItsBeam) {
  testing::EpwRecordFields hour;
  hour.gh_lux = hour.dn_lux = hour.dh_lux = "999999";
  std::string text = testing::epw_header();
  for (int h : {12, 13, 14}) {
    hour.hour = h;
    text += testing::epw_record(hour);
  }
  const EpwFile file = parse_epw(text, "irradiances.epw");
  Scene scene;
  apply_weather_hour(file, file.hours[1], scene);
  const WeatherSummary& w = *scene.weather;
  ASSERT_TRUE(w.file_direct_normal_lux);
  // The fixture's DNI 700 and DHI 150 W m⁻², its precipitable water 15 mm (taken before
  // its dew point's 1.6 cm).
  const std::optional<DaylightEfficacy> perez = perez_daylight_efficacy(
      700, 150, 90 - scene.sun.altitude_deg, 1.5,
      kPerezSolarConstantWm2 / (scene.atmosphere.earth_sun_distance_au * scene.atmosphere.earth_sun_distance_au));
  ASSERT_TRUE(perez);
  EXPECT_NEAR(*w.file_direct_normal_lux, 700 * perez->direct_lm_w, 1e-6 * 700 * perez->direct_lm_w);
  EXPECT_NEAR(*w.file_diffuse_horizontal_lux, 150 * perez->diffuse_lm_w, 1e-6 * 150 * perez->diffuse_lm_w);
  const double beam = illuminance(direct_sun_at_ground(scene.atmosphere, radians(scene.sun.altitude_deg)));
  EXPECT_NEAR(beam, *w.file_direct_normal_lux, 0.001 * *w.file_direct_normal_lux);
  const std::string said = describe_weather(w);
  EXPECT_NE(said.find("Perez et al. (1990)"), std::string::npos) << said;
}

}  // namespace
}  // namespace skylit
