// `skylit sun`: where the sun is for a site and an instant (the NREL Solar Position
// Algorithm, src/skylit/sun/solar_position.h), as a line for people or as one
// JSON object for programs.
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "skylit/core/error.h"
#include "skylit/sun/delta_t.h"
#include "skylit/sun/moon_position.h"
#include "skylit/sun/solar_position.h"

namespace skylit::cli {

namespace {

struct SunArguments {
  double latitude_deg = 0;
  double longitude_deg = 0;
  std::string time;
  double elevation_m = 0;
  std::optional<double> pressure_mbar;
  std::optional<double> temperature_c;
  std::optional<double> delta_t_s;
  bool json = false;
  bool moon = false;
};

std::string number(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// One check of a user's value: `option: expected ..., got VALUE`.
void require(bool ok, const char* option, const char* expected, double value) {
  if (ok) return;
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.10g", value);
  throw InputError(std::string(option) + ": expected " + expected + ", got " + shown);
}

void check(const SunArguments& a) {
  require(std::isfinite(a.latitude_deg) && std::abs(a.latitude_deg) <= 90.0, "--lat",
          "a latitude in degrees from -90 to 90 (north positive)", a.latitude_deg);
  require(std::isfinite(a.longitude_deg) && std::abs(a.longitude_deg) <= 180.0, "--lon",
          "a longitude in degrees from -180 to 180 (east positive)", a.longitude_deg);
  require(std::isfinite(a.elevation_m) && a.elevation_m >= -1000.0 && a.elevation_m <= 20000.0, "--elevation",
          "an elevation in metres above sea level from -1000 to 20000", a.elevation_m);
  if (a.pressure_mbar)
    require(std::isfinite(*a.pressure_mbar) && *a.pressure_mbar >= 0.0 && *a.pressure_mbar <= 2000.0, "--pressure",
            "an air pressure in mbar (hPa) from 0 to 2000", *a.pressure_mbar);
  if (a.temperature_c)
    require(std::isfinite(*a.temperature_c) && *a.temperature_c >= -100.0 && *a.temperature_c <= 100.0, "--temperature",
            "an air temperature in °C from -100 to 100", *a.temperature_c);
  if (a.delta_t_s)
    require(std::isfinite(*a.delta_t_s) && std::abs(*a.delta_t_s) <= 8000.0, "--delta-t",
            "TT - UT in seconds from -8000 to 8000", *a.delta_t_s);
}

int run_sun(const SunArguments& args) {
  check(args);
  const OffsetDateTime time = parse_offset_date_time(args.time, "--time");
  if (time.year > kSolarPositionLastYear)
    throw InputError("--time: " + args.time + " is after the year " + std::to_string(kSolarPositionLastYear) +
                     ", beyond the solar position algorithm's range");
  const SiteLocation site{args.latitude_deg, args.longitude_deg, args.elevation_m};
  const double julian_day = julian_day_ut(time);
  SpaOptions options;
  options.delta_t_s = args.delta_t_s.value_or(delta_t_estimate_s(decimal_year_of_julian_day(julian_day)));
  options.pressure_mbar = args.pressure_mbar.value_or(standard_pressure_mbar(site.elevation_m));
  options.temperature_c = args.temperature_c.value_or(standard_temperature_c(site.elevation_m));
  const SolarPosition sun = solar_position(site, julian_day, options);
  std::string moon_json, moon_line;
  if (args.moon) {
    const MoonPosition m = moon_position(site, julian_day, options);
    moon_json = ", \"moon\": {\"altitude_deg\": " + number(m.altitude_deg, 4) +
                ", \"azimuth_deg\": " + number(m.azimuth_deg, 4) + ", \"distance_km\": " + number(m.distance_km, 1) +
                ", \"phase_angle_deg\": " + number(m.phase_angle_deg, 3) +
                ", \"illuminated_fraction\": " + number(m.illuminated_fraction, 4) +
                ", \"illuminance_lx\": " + number(m.illuminance_lx, 5) + "}";
    moon_line = "moon: altitude " + number(m.altitude_deg, 4) + "°, azimuth " + number(m.azimuth_deg, 4) +
                "°, distance " + number(m.distance_km, 1) + " km, phase angle " + number(m.phase_angle_deg, 3) + "°, " +
                number(100 * m.illuminated_fraction, 1) + " % lit, " + number(m.illuminance_lx, 5) +
                " lx outside the atmosphere\n";
  }

  if (args.json) {
    std::printf(
        "{\"altitude_deg\": %s, \"azimuth_deg\": %s, \"zenith_deg\": %s, \"earth_sun_distance_au\": %s, "
        "\"equation_of_time_min\": %s, \"julian_day\": %s, \"delta_t_s\": %s, \"pressure_mbar\": %s, "
        "\"temperature_c\": %s%s}\n",
        number(sun.altitude_deg, 6).c_str(), number(sun.azimuth_deg, 6).c_str(), number(sun.zenith_deg, 6).c_str(),
        number(sun.earth_sun_distance_au, 9).c_str(), number(sun.equation_of_time_min, 4).c_str(),
        number(julian_day, 6).c_str(), number(*options.delta_t_s, 3).c_str(), number(*options.pressure_mbar, 2).c_str(),
        number(*options.temperature_c, 2).c_str(), moon_json.c_str());
  } else {
    std::printf("sun: altitude %s°, azimuth %s° (clockwise from north), zenith %s°, Earth-Sun distance %s AU\n",
                number(sun.altitude_deg, 6).c_str(), number(sun.azimuth_deg, 6).c_str(),
                number(sun.zenith_deg, 6).c_str(), number(sun.earth_sun_distance_au, 9).c_str());
    std::fputs(moon_line.c_str(), stdout);
  }
  return 0;
}

}  // namespace

CommandRunner add_sun_command(CLI::App& app) {
  auto args = std::make_shared<SunArguments>();
  CLI::App* sun = app.add_subcommand(
      "sun",
      "Print the sun's position for a site and an instant (NREL Solar Position Algorithm, ±0.0003°). "
      "Altitude is above the horizon and includes atmospheric refraction; azimuth is clockwise from "
      "north (east = 90°); zenith = 90° - altitude.");
  sun->add_option("--lat", args->latitude_deg, "Latitude in degrees, north positive (-90 to 90)")->required();
  sun->add_option("--lon", args->longitude_deg, "Longitude in degrees, east positive (-180 to 180)")->required();
  sun->add_option("--time", args->time,
                  "Instant as ISO 8601 with a UTC offset, e.g. 2026-06-21T07:00:00+09:00 or "
                  "2026-06-20T22:00:00Z (a time without offset is refused as ambiguous)")
      ->required();
  sun->add_option("--elevation", args->elevation_m, "Site elevation in metres above sea level (default 0)");
  sun->add_option("--pressure", args->pressure_mbar,
                  "Air pressure in mbar (hPa), for refraction (default: standard atmosphere at the elevation, "
                  "1013.25 at sea level)");
  sun->add_option("--temperature", args->temperature_c,
                  "Air temperature in °C, for refraction (default: standard atmosphere at the elevation, 15 at "
                  "sea level)");
  sun->add_option("--delta-t", args->delta_t_s,
                  "TT - UT in seconds (default: Espenak & Meeus estimate for the date, e.g. about 75 s in 2025 "
                  "where the measured value is about 69 s)");
  sun->add_flag("--moon", args->moon,
                "Also give the moon: position (Meeus ch. 47), phase angle, lit fraction and its illuminance outside "
                "the atmosphere (Krisciunas & Schaefer 1991); docs/sun-position.md");
  sun->add_flag("--json", args->json,
                "Print one JSON object: altitude_deg, azimuth_deg, zenith_deg, earth_sun_distance_au, "
                "equation_of_time_min, julian_day (UT), and the delta_t_s, pressure_mbar, temperature_c used");
  return [sun, args] { return sun->parsed() ? run_sun(*args) : -1; };
}

}  // namespace skylit::cli
