// The model against a whole weather file, hours binned by opaque sky cover: how the
// diffuse and global horizontal illuminance of the hour's air, sky and clouds (as the
// renderer sees them: check_weather_model) compare with the file's. A measurement, not a
// test: it runs with SKYLIT_EPW_SURVEY=N (N hours per bin, evenly spread over the year;
// each takes one to a few seconds) and prints its table (docs/weather.md quotes it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "skylit/io/weather/epw_reader.h"
#include "skylit/io/weather/weather_conditions.h"
#include "skylit/sun/solar_position.h"

namespace skylit {
namespace {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

TEST(WeatherSurvey, TheSharedFileByOpaqueCover) {
  const char* asked = std::getenv("SKYLIT_EPW_SURVEY");
  if (!asked) GTEST_SKIP() << "a measurement: SKYLIT_EPW_SURVEY=N runs N hours per bin of cover";
  const std::filesystem::path path =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/NLD_Amsterdam062400_IWEC.epw";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const EpwFile file = read_epw(path);
  const size_t per_bin = static_cast<size_t>(std::max(1, std::atoi(asked)));
  struct Bin {
    const char* name;
    double lo, hi;
    std::vector<const EpwHour*> hours;
  };
  std::vector<Bin> bins{{"0", 0, 0, {}}, {"1-3", 1, 3, {}}, {"4-6", 4, 6, {}}, {"7-9", 7, 9, {}}, {"10", 10, 10, {}}};
  for (const EpwHour& h : file.hours) {
    if (!h.opaque_sky_cover_tenths || !h.direct_normal_lux || !h.diffuse_horizontal_lux || !h.global_horizontal_lux)
      continue;
    // Daylight, away from the horizon: the sun at the hour's middle (as apply_weather_hour
    // places it, without refraction) at least 5° high.
    OffsetDateTime when;
    when.year = 2001, when.month = h.month, when.day = h.day, when.hour = h.hour - 1, when.minute = 30;
    when.utc_offset_minutes = static_cast<int>(std::lround(file.location.time_zone_h * 60));
    const SiteLocation station{file.location.latitude_deg, file.location.longitude_deg, 0};
    if (solar_position(station, when).altitude_deg < 5) continue;
    for (Bin& b : bins)
      if (*h.opaque_sky_cover_tenths >= b.lo && *h.opaque_sky_cover_tenths <= b.hi) b.hours.push_back(&h);
  }
  std::printf(
      "cover  hours(of)  DH model/file: median [p10, p90] (min, max) within 25%%  |  GH: median [p10, p90] "
      "(min, max) within 10%%\n");
  for (const Bin& b : bins) {
    std::vector<double> dh, gh, clear_dh;
    const size_t n = std::min(per_bin, b.hours.size());
    for (size_t i = 0; i < n; ++i) {
      const EpwHour& h = *b.hours[i * b.hours.size() / n];
      Scene scene;
      apply_weather_hour(file, h, scene);
      check_weather_model(scene);
      const WeatherSummary& w = *scene.weather;
      if (*h.diffuse_horizontal_lux > 0) {
        dh.push_back(*w.model_diffuse_horizontal_lux / *h.diffuse_horizontal_lux);
        clear_dh.push_back(*w.clear_sky_diffuse_horizontal_lux / *h.diffuse_horizontal_lux);
      }
      if (*h.global_horizontal_lux > 0) gh.push_back(*w.model_global_horizontal_lux / *h.global_horizontal_lux);
      if (std::getenv("SKYLIT_EPW_SURVEY_HOURS"))
        std::printf("  %s cover %.0f sun %.1f aod %.3f: DH %.0f/%.0f GH %.0f/%.0f\n", w.record.c_str(),
                    *h.opaque_sky_cover_tenths, w.sun_altitude_deg, scene.atmosphere.aerosol.aod_550,
                    *w.model_diffuse_horizontal_lux, *h.diffuse_horizontal_lux, *w.model_global_horizontal_lux,
                    *h.global_horizontal_lux);
    }
    auto within = [](const std::vector<double>& v, double tol) {
      return std::count_if(v.begin(), v.end(), [&](double r) { return std::abs(r - 1) <= tol; });
    };
    std::printf("%-5s  %3zu(%4zu)  %.3f [%.3f, %.3f] (%.3f, %.3f) %3ld  |  %.3f [%.3f, %.3f] (%.3f, %.3f) %3ld\n",
                b.name, n, b.hours.size(), quantile(dh, 0.5), quantile(dh, 0.1), quantile(dh, 0.9), quantile(dh, 0),
                quantile(dh, 1), static_cast<long>(within(dh, 0.25)), quantile(gh, 0.5), quantile(gh, 0.1),
                quantile(gh, 0.9), quantile(gh, 0), quantile(gh, 1), static_cast<long>(within(gh, 0.10)));
    std::printf("       the air's own diffuse light, clouds left out: DH median %.3f [%.3f, %.3f]\n",
                quantile(clear_dh, 0.5), quantile(clear_dh, 0.1), quantile(clear_dh, 0.9));
  }
}

}  // namespace
}  // namespace skylit

namespace skylit {
namespace {
// Also a measurement: the clouded sky's diffuse light of one hour (SKYLIT_EPW_SCAN=MM-DD-hh)
// as the generated layer's extinction is scaled, clouds lit as if alone. It rises and
// falls (thin clouds scatter the sun forward; docs/weather.md quotes it), so it is not
// what is fitted.
TEST(WeatherSurvey, ScanCloudExtinction) {
  const char* asked = std::getenv("SKYLIT_EPW_SCAN");
  if (!asked) GTEST_SKIP();
  const EpwFile file =
      read_epw(std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/NLD_Amsterdam062400_IWEC.epw");
  int m = 0, d = 0, hr = 0;
  std::sscanf(asked, "%d-%d-%d", &m, &d, &hr);
  for (double f : {0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0}) {
    Scene scene;
    apply_weather_hour(file, epw_hour_containing(file, m, d, hr, 0, "t"), scene);
    if (!scene.cloud_layer) GTEST_SKIP() << "no layer";
    scene.cloud_layer->extinction *= f;
    scene.cloud_layer->diffuse_horizontal_lux.reset();  // lit as if alone
    check_weather_model(scene);
    std::printf("x%.3f  DH %.0f / file %.0f (clear %.0f)\n", f, *scene.weather->model_diffuse_horizontal_lux,
                *scene.weather->file_diffuse_horizontal_lux, *scene.weather->clear_sky_diffuse_horizontal_lux);
  }
}
}  // namespace
}  // namespace skylit
