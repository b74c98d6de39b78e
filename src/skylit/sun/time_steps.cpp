// Steps through civil time for sun studies (time_steps.h).
#include "skylit/sun/time_steps.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "skylit/core/error.h"

namespace skylit {

namespace {

constexpr int64_t kSecondsPerDay = 86400;
constexpr int64_t kMaxStepSeconds = 366 * kSecondsPerDay;

[[noreturn]] void fail(std::string_view where, const std::string& what) {
  throw InputError(std::string(where) + ": " + what);
}

// Appended piece by piece: `"\"" + std::string` trips GCC 12's false -Wrestrict (GCC bug 105329).
std::string quoted(std::string_view text) {
  std::string result = "\"";
  result += text;
  result += '"';
  return result;
}

// Whole seconds of the local clock since 1970-01-01T00:00 on that clock; the fraction of
// a second stays in the OffsetDateTime.
int64_t local_seconds(const OffsetDateTime& t) {
  return static_cast<int64_t>(days_from_civil(t.year, t.month, t.day)) * kSecondsPerDay + t.hour * 3600 +
         t.minute * 60 + static_cast<int64_t>(std::floor(t.second));
}

int64_t floor_div(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0); }

std::string two_digits(int value) {
  char text[8];
  std::snprintf(text, sizeof text, "%02d", value);
  return text;
}

}  // namespace

int64_t parse_step_seconds(std::string_view text, std::string_view where) {
  const auto expected = [&] { fail(where, "expected a step such as 10min, 30s, 1h or 1d, found " + quoted(text)); };
  double amount = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), amount);
  if (error != std::errc() || !std::isfinite(amount)) expected();
  const std::string_view unit = text.substr(static_cast<std::size_t>(end - text.data()));
  double seconds_per_unit = 0;
  if (unit == "s")
    seconds_per_unit = 1;
  else if (unit == "min" || unit == "m")
    seconds_per_unit = 60;
  else if (unit == "h")
    seconds_per_unit = 3600;
  else if (unit == "d")
    seconds_per_unit = kSecondsPerDay;
  else
    expected();
  const double seconds = amount * seconds_per_unit;
  if (!(seconds >= 1) || seconds > kMaxStepSeconds || seconds != std::floor(seconds))
    fail(where, quoted(text) + " is not a whole number of seconds from 1 s to 366 d");
  return static_cast<int64_t>(seconds);
}

OffsetDateTime add_seconds(const OffsetDateTime& time, int64_t seconds) {
  const int64_t total = local_seconds(time) + seconds;
  const int64_t days = floor_div(total, kSecondsPerDay);
  int64_t of_day = total - days * kSecondsPerDay;
  OffsetDateTime out = time;
  out.second = time.second - std::floor(time.second) + static_cast<double>(of_day % 60);
  of_day /= 60;
  out.minute = static_cast<int>(of_day % 60);
  out.hour = static_cast<int>(of_day / 60);
  // The calendar date of `days`: the year by estimate and correction, then the month.
  int year = static_cast<int>(1970 + floor_div(days * 400, 146097));
  while (days_from_civil(year + 1, 1, 1) <= days) ++year;
  while (days_from_civil(year, 1, 1) > days) --year;
  int month = 1;
  while (month < 12 && days_from_civil(year, month + 1, 1) <= days) ++month;
  out.year = year;
  out.month = month;
  out.day = static_cast<int>(days - days_from_civil(year, month, 1)) + 1;
  return out;
}

double seconds_between(const OffsetDateTime& a, const OffsetDateTime& b) {
  const auto utc = [](const OffsetDateTime& t) {
    return static_cast<double>(local_seconds(t) - int64_t{t.utc_offset_minutes} * 60) +
           (t.second - std::floor(t.second));
  };
  return utc(b) - utc(a);
}

std::vector<OffsetDateTime> instants_every(const OffsetDateTime& from, const OffsetDateTime& to, int64_t step_s,
                                           std::string_view where) {
  const double span_s = seconds_between(from, to);
  if (span_s < 0)
    fail(where, "the end " + format_offset_date_time(to) + " comes before the start " + format_offset_date_time(from));
  const double count = std::floor(span_s / static_cast<double>(step_s)) + 1;
  if (count > static_cast<double>(kMaxStudyInstants))
    fail(where, "the range holds " + std::to_string(static_cast<long long>(count)) + " instants, more than " +
                    std::to_string(kMaxStudyInstants) + "; take a longer step");
  std::vector<OffsetDateTime> instants;
  for (int64_t i = 0; i < static_cast<int64_t>(count); ++i) instants.push_back(add_seconds(from, i * step_s));
  return instants;
}

OffsetDateTime parse_clock_time(std::string_view text, int default_offset_minutes, std::string_view where) {
  // The clock part is "hh:mm" or "hh:mm:ss[.f]"; anything after it is the offset.
  std::string full = "2000-01-01T" + std::string(text);
  const bool has_offset = text.find_first_of("Z+-") != std::string_view::npos;
  if (!has_offset) full += format_offset(default_offset_minutes);
  return parse_offset_date_time(full, where);
}

std::vector<OffsetDateTime> instants_on_dates(std::string_view dates, int year, const OffsetDateTime& at,
                                              std::string_view where) {
  std::vector<OffsetDateTime> instants;
  std::size_t start = 0;
  while (start <= dates.size()) {
    const std::size_t comma = std::min(dates.find(',', start), dates.size());
    const std::string_view date = dates.substr(start, comma - start);
    const std::string year_part = date.size() == 5 ? std::to_string(year) + "-" : "";
    if (date.size() != 5 && date.size() != 10)
      fail(where, "expected dates as MM-DD or YYYY-MM-DD separated by commas, found " + quoted(date));
    char iso[64];
    std::snprintf(iso, sizeof iso, "%s%.*sT%s:%s%s", year_part.c_str(), static_cast<int>(date.size()), date.data(),
                  two_digits(at.hour).c_str(), two_digits(at.minute).c_str(),
                  format_offset(at.utc_offset_minutes).c_str());
    OffsetDateTime t = parse_offset_date_time(iso, std::string(where) + " (" + std::string(date) + ")");
    t.second = at.second;
    instants.push_back(t);
    if (instants.size() > kMaxStudyInstants) fail(where, "more than " + std::to_string(kMaxStudyInstants) + " dates");
    start = comma + 1;
  }
  return instants;
}

std::string format_date(const OffsetDateTime& t) {
  char text[32];
  std::snprintf(text, sizeof text, "%04d-%02d-%02d", t.year, t.month, t.day);
  return text;
}

std::string format_clock(const OffsetDateTime& t) {
  std::string text = two_digits(t.hour) + ":" + two_digits(t.minute);
  if (t.second != 0) {
    char seconds[16];
    std::snprintf(seconds, sizeof seconds, ":%02d", static_cast<int>(t.second));
    text += seconds;
  }
  return text;
}

std::string format_offset(int utc_offset_minutes) {
  if (utc_offset_minutes == 0) return "Z";
  const int magnitude = std::abs(utc_offset_minutes);
  std::string text(1, utc_offset_minutes < 0 ? '-' : '+');  // not `"-" + std::string`: GCC bug 105329
  text += two_digits(magnitude / 60);
  text += ':';
  text += two_digits(magnitude % 60);
  return text;
}

std::string format_offset_date_time(const OffsetDateTime& t) {
  return format_date(t) + "T" + format_clock(t) + format_offset(t.utc_offset_minutes);
}

}  // namespace skylit
