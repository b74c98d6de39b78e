// EnergyPlus weather files (EPW): the site from the LOCATION line and the hourly
// records. Format: EnergyPlus "Auxiliary Programs", ch. "Weather Converter Program",
// section "EnergyPlus Weather File (EPW) Data Dictionary" (docs/weather.md).
//
// Each record describes the hour that ENDS at its clock time, in the site's local
// STANDARD time (no daylight saving): hour 13 is 12:00–13:00. Its radiation and
// illuminance are that hour's means.
//
// Missing values are written as the format's codes (9999 for radiation, 999999 for
// illuminance, 99 for sky cover, 9999 for visibility, 99999 for the ceiling, 999 for
// snow depth...); a value at or past its code, or outside the field's physical range,
// becomes an empty optional, and the field's name is listed in `EpwHour::missing`.
// Text that is not a number, a wrong number of fields, or a date that does not exist
// is an InputError "<file>:<line>: field <n> (<name>): <what is wrong>".
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit {

struct EpwLocation {
  std::string city, region, country, source, wmo_station;
  double latitude_deg = 0;   // north positive
  double longitude_deg = 0;  // east positive
  double time_zone_h = 0;    // standard time minus UTC, hours
  double elevation_m = 0;    // above sea level
};

// One hourly record: what skylit uses of it, in the file's units.
struct EpwHour {
  int line = 0;  // in the file, for messages
  int year = 0, month = 1, day = 1;
  int hour = 1;     // 1 to 24: the hour ending at this clock time (local standard time)
  int minute = 60;  // as written (60 or 0 in hourly files)
  std::optional<double> dry_bulb_c, dew_point_c, relative_humidity_pct, pressure_pa;
  std::optional<double> global_horizontal_w_m2, direct_normal_w_m2, diffuse_horizontal_w_m2;
  std::optional<double> global_horizontal_lux, direct_normal_lux, diffuse_horizontal_lux;
  std::optional<double> zenith_luminance_cd_m2;
  std::optional<double> total_sky_cover_tenths, opaque_sky_cover_tenths;
  std::optional<double> visibility_km;
  std::optional<double> ceiling_height_m;  // 77777: unlimited, 88888: cirroform (both kept)
  std::optional<double> precipitable_water_mm, aerosol_optical_depth;
  std::optional<double> snow_depth_cm;
  std::optional<double> albedo;
  // The names of the fields above that were missing (their code) or out of range.
  std::vector<std::string> missing;
};

struct EpwFile {
  std::string name;  // for messages
  EpwLocation location;
  std::vector<EpwHour> hours;  // in the file's order
};

EpwFile parse_epw(std::string_view text, const std::string& name);
EpwFile read_epw(const std::filesystem::path& file);

// The record of the hour that contains local standard time `hh:mm` on month-day: the
// one ending at the next whole hour, so that 12:30 and 13:00 both give hour 13
// (12:00–13:00), and 00:00 gives the previous day's hour 24. Throws InputError naming
// `where` if the file has no such record.
const EpwHour& epw_hour_containing(const EpwFile& file, int month, int day, int hour, int minute,
                                   const std::string& where);

}  // namespace skylit
