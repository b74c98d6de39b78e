// The instants of a sun study (`skylit animate`, docs/animations.md): a range of clock
// times at a fixed step, or one clock time on several dates. Arithmetic on civil
// date-times that keeps each instant's UTC offset, so that labels read as the clock
// the user gave.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "skylit/sun/time.h"

namespace skylit {

// The most instants one study may hold: a year every 10 minutes is 52,560.
inline constexpr std::size_t kMaxStudyInstants = 100000;

// A step such as "10min", "30s", "1h", "1.5h" or "1d" in whole seconds (> 0, at most a
// year). InputError beginning with `where` otherwise.
int64_t parse_step_seconds(std::string_view text, std::string_view where);

// `time` moved by `seconds` (either sign) on its own clock: the same UTC offset, the
// calendar carried over days, months and years.
OffsetDateTime add_seconds(const OffsetDateTime& time, int64_t seconds);

// Seconds from a to b, as instants (their offsets taken into account).
double seconds_between(const OffsetDateTime& a, const OffsetDateTime& b);

// from, from + step, ... up to and including `to` (compared as instants), on from's
// clock. InputError beginning with `where` if `to` comes before `from` or the study
// would hold more than kMaxStudyInstants.
std::vector<OffsetDateTime> instants_every(const OffsetDateTime& from, const OffsetDateTime& to, int64_t step_s,
                                           std::string_view where);

// "hh:mm[:ss]" optionally followed by an offset (Z, ±hh:mm, ±hhmm, ±hh) as in
// parse_offset_date_time; a missing offset is `default_offset_minutes`.
OffsetDateTime parse_clock_time(std::string_view text, int default_offset_minutes, std::string_view where);

// Dates "MM-DD" (in `year`) or "YYYY-MM-DD", separated by commas, each at the clock
// time of `at` (its hour, minute, second and offset). In the order given.
std::vector<OffsetDateTime> instants_on_dates(std::string_view dates, int year, const OffsetDateTime& at,
                                              std::string_view where);

// "2026-06-21", "07:00" (":ss" when the seconds are not whole zero) and "+02:00" / "Z".
std::string format_date(const OffsetDateTime& time);
std::string format_clock(const OffsetDateTime& time);
std::string format_offset(int utc_offset_minutes);
// The full ISO 8601 form: format_date + "T" + format_clock + format_offset.
std::string format_offset_date_time(const OffsetDateTime& time);

}  // namespace skylit
