#include "skylit/io/weather/epw_reader.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/core/utf8.h"
#include "skylit/sun/time.h"

namespace skylit {

namespace {

// A numeric field of a record: its 0-based position, its name (the data dictionary's),
// the code that marks it missing (a value at or above it is missing) and the range of
// physical values (the dictionary's minimum and maximum, or the physical bounds).
struct FieldSpec {
  int index;
  const char* name;
  double missing_at_or_above;
  double lo, hi;
  std::optional<double> EpwHour::*member;
};

// Missing codes: EnergyPlus Auxiliary Programs, "Weather Converter Program", EPW data
// dictionary ("missing" of each field). Ranges: its "minimum"/"maximum" where it gives
// them, else the physical bounds.
constexpr std::array kFields{
    FieldSpec{6, "dry bulb temperature", 99.9, -70, 70, &EpwHour::dry_bulb_c},
    FieldSpec{7, "dew point temperature", 99.9, -70, 70, &EpwHour::dew_point_c},
    FieldSpec{8, "relative humidity", 999, 0, 110, &EpwHour::relative_humidity_pct},
    FieldSpec{9, "atmospheric station pressure", 999999, 31000, 120000, &EpwHour::pressure_pa},
    FieldSpec{13, "global horizontal radiation", 9999, 0, 2000, &EpwHour::global_horizontal_w_m2},
    FieldSpec{14, "direct normal radiation", 9999, 0, 2000, &EpwHour::direct_normal_w_m2},
    FieldSpec{15, "diffuse horizontal radiation", 9999, 0, 2000, &EpwHour::diffuse_horizontal_w_m2},
    FieldSpec{16, "global horizontal illuminance", 999900, 0, 250000, &EpwHour::global_horizontal_lux},
    FieldSpec{17, "direct normal illuminance", 999900, 0, 250000, &EpwHour::direct_normal_lux},
    FieldSpec{18, "diffuse horizontal illuminance", 999900, 0, 250000, &EpwHour::diffuse_horizontal_lux},
    FieldSpec{19, "zenith luminance", 9999, 0, 9998, &EpwHour::zenith_luminance_cd_m2},
    FieldSpec{22, "total sky cover", 99, 0, 10, &EpwHour::total_sky_cover_tenths},
    FieldSpec{23, "opaque sky cover", 99, 0, 10, &EpwHour::opaque_sky_cover_tenths},
    FieldSpec{24, "visibility", 9999, 0, 9998, &EpwHour::visibility_km},
    FieldSpec{25, "ceiling height", 99999, 0, 99998, &EpwHour::ceiling_height_m},
    FieldSpec{28, "precipitable water", 999, 0, 998, &EpwHour::precipitable_water_mm},
    FieldSpec{29, "aerosol optical depth", 0.999, 0, 0.998, &EpwHour::aerosol_optical_depth},
    FieldSpec{30, "snow depth", 999, 0, 998, &EpwHour::snow_depth_cm},
    FieldSpec{32, "albedo", 999, 0, 1, &EpwHour::albedo},
};
// Records need the fields through snow depth; albedo and the precipitation fields after
// it are absent from some older files.
constexpr size_t kRequiredFields = 31;
constexpr size_t kMaxFields = 35;

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

class LineReader {
 public:
  LineReader(const std::string& name, int line, std::vector<std::string_view> fields)
      : name_(name), line_(line), fields_(std::move(fields)) {}

  size_t size() const { return fields_.size(); }
  [[noreturn]] void fail(int index, const char* field, const std::string& message) const {
    throw InputError(name_ + ":" + std::to_string(line_) + ": field " + std::to_string(index + 1) + " (" + field +
                     "): " + message);
  }
  // A number, or empty when the field is blank.
  std::optional<double> number(int index, const char* field) const {
    const std::string_view text = trimmed(fields_[static_cast<size_t>(index)]);
    if (text.empty()) return std::nullopt;
    double value = 0;
    const char* begin = text.data() + (text.front() == '+' ? 1 : 0);
    const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
      fail(index, field, "expected a number, found " + quote_excerpt(text));
    return value;
  }
  double required(int index, const char* field) const {
    if (auto v = number(index, field)) return *v;
    fail(index, field, "expected a number, found nothing");
  }
  int whole(int index, const char* field, int lo, int hi) const {
    const double v = required(index, field);
    if (!(v >= lo && v <= hi && v == std::floor(v)))
      fail(index, field,
           "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", found " +
               quote_excerpt(trimmed(fields_[static_cast<size_t>(index)])));
    return static_cast<int>(v);
  }
  std::string text(int index) const { return std::string(trimmed(fields_[static_cast<size_t>(index)])); }
  // Whether every field from `first` on is blank (trailing commas some exports write).
  bool blank_from(size_t first) const {
    for (size_t i = first; i < fields_.size(); ++i)
      if (!trimmed(fields_[i]).empty()) return false;
    return true;
  }

 private:
  const std::string& name_;
  int line_;
  std::vector<std::string_view> fields_;
};

EpwLocation read_location(const LineReader& r, const std::string& name) {
  if (r.size() < 10)
    throw InputError(name + ":1: the LOCATION line has " + std::to_string(r.size()) +
                     " fields, expected 10 (LOCATION, city, region, country, source, WMO, latitude, longitude, "
                     "time zone, elevation)");
  EpwLocation l;
  // Station names in Latin-1, as older files and some exports write them, become UTF-8.
  l.city = utf8_or_latin1(r.text(1)), l.region = utf8_or_latin1(r.text(2)), l.country = utf8_or_latin1(r.text(3));
  l.source = utf8_or_latin1(r.text(4)), l.wmo_station = utf8_or_latin1(r.text(5));
  const auto in = [&](int index, const char* field, double lo, double hi) {
    const double v = r.required(index, field);
    if (!(v >= lo && v <= hi)) {
      char range[64];
      std::snprintf(range, sizeof range, "must lie within %g to %g", lo, hi);
      r.fail(index, field, range);
    }
    return v;
  };
  l.latitude_deg = in(6, "latitude", -90, 90);
  l.longitude_deg = in(7, "longitude", -180, 180);
  l.time_zone_h = in(8, "time zone", -12, 14);
  l.elevation_m = in(9, "elevation", -1000, 9999.9);
  return l;
}

EpwHour read_record(const LineReader& r, int line, const std::string& name) {
  if (r.size() < kRequiredFields || (r.size() > kMaxFields && !r.blank_from(kMaxFields)))
    throw InputError(name + ":" + std::to_string(line) + ": a data record has " + std::to_string(r.size()) +
                     " fields, expected 35 (at least the 31 up to snow depth)");
  EpwHour h;
  h.line = line;
  h.year = r.whole(0, "year", 1, 9999);
  h.month = r.whole(1, "month", 1, 12);
  // February 29 is accepted in any year: typical years are stitched from different years.
  const int month_length = h.month == 2 ? 29 : days_in_month(2001, h.month);
  h.day = r.whole(2, "day", 1, month_length);
  h.hour = r.whole(3, "hour", 1, 24);
  h.minute = r.whole(4, "minute", 0, 60);
  for (const FieldSpec& f : kFields) {
    if (static_cast<size_t>(f.index) >= r.size()) {
      h.missing.emplace_back(f.name);
      continue;
    }
    const std::optional<double> v = r.number(f.index, f.name);
    if (v && *v < f.missing_at_or_above && *v >= f.lo && *v <= f.hi)
      h.*f.member = *v;
    else
      h.missing.emplace_back(f.name);
  }
  return h;
}

}  // namespace

EpwFile parse_epw(std::string_view text, const std::string& name) {
  EpwFile file;
  file.name = name;
  int line_number = 0;
  bool location_seen = false, data_periods_seen = false;
  text = without_byte_order_mark(text);
  size_t start = 0;
  while (start < text.size()) {
    // Lines end in LF, CR LF (Windows) or a lone CR (classic Mac OS exports).
    size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
    ++line_number;
    if (trimmed(line).empty()) continue;
    const LineReader r(name, line_number, split_commas(line));
    if (!location_seen) {
      if (r.text(0) != "LOCATION")
        throw InputError(name + ":" + std::to_string(line_number) +
                         ": an EPW file begins with its LOCATION line, found " + quote_excerpt(line));
      file.location = read_location(r, name);
      location_seen = true;
    } else if (!data_periods_seen) {
      // The other header lines (design conditions, periods, ground temperatures,
      // holidays, comments) say nothing skylit uses; DATA PERIODS is the last. They
      // begin with their names; a line that begins with a digit is a record (a year).
      data_periods_seen = r.text(0) == "DATA PERIODS";
      if (!data_periods_seen && std::isdigit(static_cast<unsigned char>(trimmed(line).front())))
        throw InputError(name + ":" + std::to_string(line_number) +
                         ": a record before the DATA PERIODS line, which ends the header (is it missing?)");
    } else {
      file.hours.push_back(read_record(r, line_number, name));
    }
  }
  if (!location_seen) throw InputError(name + ":1: empty file: an EPW file begins with its LOCATION line");
  if (!data_periods_seen)
    throw InputError(name + ":" + std::to_string(line_number) + ": no DATA PERIODS line ends the header");
  if (file.hours.empty())
    throw InputError(name + ":" + std::to_string(line_number) + ": no hourly records after DATA PERIODS");
  return file;
}

EpwFile read_epw(const std::filesystem::path& file) {
  return parse_epw(read_text_file(file, "weather file"), file.string());
}

const EpwHour& epw_hour_containing(const EpwFile& file, int month, int day, int hour, int minute,
                                   const std::string& where) {
  const bool on_the_hour = minute == 0;
  // 00:00 closes the previous day's hour 24: the record before that day's hour 1.
  const int wanted = on_the_hour ? (hour == 0 ? 1 : hour) : hour + 1;
  const EpwHour* found = nullptr;
  size_t index = 0;
  for (size_t i = 0; i < file.hours.size(); ++i) {
    const EpwHour& h = file.hours[i];
    if (h.month != month || h.day != day || h.hour != wanted) continue;
    // Sub-hourly files: the last record of the hour ends it; midnight needs the first of hour 1.
    if (!found || !(on_the_hour && hour == 0)) found = &h, index = i;
  }
  if (!found) {
    char shown[32];
    std::snprintf(shown, sizeof shown, "%02d-%02dT%02d:%02d", month, day, hour, minute);
    throw InputError(where + ": " + file.name + " has no record for " + shown + " (hour " + std::to_string(wanted) +
                     " of that day)");
  }
  if (!(on_the_hour && hour == 0)) return *found;
  // Midnight: the record before, which must be the day before's hour 24 (a typical year
  // wraps from 12-31 to 01-01; a file holding only part of a year may not have it).
  const EpwHour& before = file.hours[(index + file.hours.size() - 1) % file.hours.size()];
  const int previous_month = day > 1 ? month : month == 1 ? 12 : month - 1;
  const bool day_before =
      before.month == previous_month &&
      (day > 1 ? before.day == day - 1
               : before.day == days_in_month(2001, previous_month) || (previous_month == 2 && before.day == 29));
  if (before.hour != 24 || !day_before) {
    char shown[32];
    std::snprintf(shown, sizeof shown, "%02d-%02dT00:00", month, day);
    throw InputError(where + ": " + file.name + " has no record for " + shown +
                     " (hour 24 of the day before; the record before that day's hour 1 is line " +
                     std::to_string(before.line) + ")");
  }
  return before;
}

}  // namespace skylit
