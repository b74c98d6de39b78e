// What a scene took from a weather file's hour (io/weather/weather_conditions.h), kept
// so that `skylit info` can say it, with the model's check against the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace skylit {

// How close the model must come to the file, as a fraction of the file's value
// (docs/weather.md: the direct beam is fitted, so only the fit's convergence and the
// aerosol's bounds can miss it; global and diffuse come from the model's own sky).
inline constexpr double kWeatherDirectNormalTolerance = 0.02;
inline constexpr double kWeatherGlobalHorizontalTolerance = 0.10;
inline constexpr double kWeatherDiffuseHorizontalTolerance = 0.25;

struct WeatherSummary {
  std::string file;
  std::string station;  // city, country, source and WMO number as the file gives them
  double latitude_deg = 0, longitude_deg = 0, time_zone_h = 0, elevation_m = 0;
  // How far the station lies from the site the sun is placed for (0 when no site but the
  // station's was given).
  double station_distance_km = 0;
  std::string record;                  // which record, e.g. "06-21 hour 13 (12:00-13:00 standard time), line 4116"
  std::string sun_time;                // the instant the sun is placed at (the hour's middle), ISO 8601
  std::vector<std::string> missing;    // this record's fields that were missing or out of range
  std::vector<std::string> decisions;  // one line each: aerosol, sky, clouds, fog, ground
  // The file's values and the model's, in lx (photopic: the band skylit renders).
  std::optional<double> file_direct_normal_lux, file_diffuse_horizontal_lux, file_global_horizontal_lux;
  std::optional<double> model_direct_normal_lux, model_diffuse_horizontal_lux, model_global_horizontal_lux;
  // The clear sky's diffuse horizontal illuminance alone (the model's above counts the
  // clouds as rendered, where there are any).
  std::optional<double> clear_sky_diffuse_horizontal_lux;
  // The part of the hour the direct beam is taken to shine: 1 − opaque sky cover up to
  // 3/10 of it, above that the file's beam over the clear air's (docs/weather.md).
  double clear_fraction = 1.0;
  double sun_altitude_deg = 0;
};

}  // namespace skylit
