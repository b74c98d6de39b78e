// Civil date-times with a UTC offset, as users write them (ISO 8601 / RFC 3339, e.g.
// 2026-06-21T07:00:00+09:00), and their Julian Day in Universal Time, which is what
// the solar position algorithm (solar_position.h) counts time in.
//
// Dates are in the proleptic Gregorian calendar, as ISO 8601 defines them, also
// before 1582. The Julian Day follows Meeus, "Astronomical Algorithms" (2nd ed.,
// 1998), ch. 7: JD 2451545.0 is 2000-01-01 12:00 UT.
#pragma once

#include <string_view>

namespace skylit {

// A date and time of day on a local clock, and that clock's offset from UTC.
struct OffsetDateTime {
  int year = 2000;             // four digits, 0000 to 9999
  int month = 1;               // 1 to 12
  int day = 1;                 // 1 to the month's length
  int hour = 0;                // 0 to 23
  int minute = 0;              // 0 to 59
  double second = 0;           // 0 to < 61 (60 is a leap second)
  int utc_offset_minutes = 0;  // local time minus UTC: +09:00 is 540, Z is 0
};

// Reads `YYYY-MM-DDThh:mm[:ss[.fff]]` followed by `Z`, `±hh:mm`, `±hhmm` or `±hh`.
// A time without an offset is refused: a local time alone does not say when it is.
// Throws InputError whose message begins with `where` (e.g. "scene.json: time") and
// says what was expected.
OffsetDateTime parse_offset_date_time(std::string_view text, std::string_view where);

// The Julian Day of that instant in Universal Time (UTC taken as UT; see
// SpaOptions::delta_ut1_s for the difference, below one second).
double julian_day_ut(const OffsetDateTime& time);

// Days from 1970-01-01 to the given proleptic Gregorian date (negative before it).
long long days_from_civil(long long year, int month, int day);

bool is_leap_year(int year);             // proleptic Gregorian
int days_in_month(int year, int month);  // month 1 to 12

}  // namespace skylit
