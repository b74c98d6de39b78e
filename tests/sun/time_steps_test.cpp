// The instants of a sun study (sun/time_steps.h): steps that cross days, months, leap
// days and years on the user's own clock, checked against the Julian Day (time.h), an
// independent count of days; ranges and dates in order; and the errors.
#include "skylit/sun/time_steps.h"

#include <gtest/gtest.h>

#include "../test_support.h"

namespace skylit {
namespace {

OffsetDateTime at(const char* iso) { return parse_offset_date_time(iso, "test"); }

TEST(TimeSteps, StepsCrossDaysMonthsLeapDaysAndYears) {
  EXPECT_EQ(format_offset_date_time(add_seconds(at("2024-02-28T23:30+05:30"), 3600)), "2024-02-29T00:30+05:30");
  EXPECT_EQ(format_offset_date_time(add_seconds(at("2023-02-28T23:30Z"), 3600)), "2023-03-01T00:30Z");
  EXPECT_EQ(format_offset_date_time(add_seconds(at("2026-12-31T23:50-03:00"), 600)), "2027-01-01T00:00-03:00");
  EXPECT_EQ(format_offset_date_time(add_seconds(at("2026-01-01T00:00Z"), -1)), "2025-12-31T23:59:59Z");
  // Any step: the Julian Days (computed from the calendar by time.cpp) differ by the
  // step, to the double's resolution near 2.46e6 days (about 40 µs).
  const OffsetDateTime start = at("2026-03-29T01:00+01:00");
  for (const int64_t step : {1LL, 59LL, 3600LL, 86399LL, 86400LL * 400 + 7, -86400LL * 1000}) {
    const OffsetDateTime moved = add_seconds(start, step);
    EXPECT_NEAR((julian_day_ut(moved) - julian_day_ut(start)) * 86400.0, static_cast<double>(step), 1e-4) << step;
    EXPECT_EQ(moved.utc_offset_minutes, 60);
  }
}

TEST(TimeSteps, RangeIncludesItsEndAndKeepsTheStartsClock) {
  const auto day = instants_every(at("2026-06-21T05:00+02:00"), at("2026-06-21T19:00+02:00"), 3600, "test");
  ASSERT_EQ(day.size(), 15u);
  EXPECT_EQ(format_offset_date_time(day.front()), "2026-06-21T05:00+02:00");
  EXPECT_EQ(format_offset_date_time(day.back()), "2026-06-21T19:00+02:00");
  for (std::size_t i = 1; i < day.size(); ++i) EXPECT_DOUBLE_EQ(seconds_between(day[i - 1], day[i]), 3600);
  // An end on another clock is the same instant: 17:10Z is 19:10+02:00, past 19:00 but
  // short of 19:20, so the last frame is 19:00.
  const auto other = instants_every(at("2026-06-21T18:00+02:00"), at("2026-06-21T17:10Z"), 1200, "test");
  ASSERT_EQ(other.size(), 4u);
  EXPECT_EQ(format_clock(other.back()), "19:00");
}

TEST(TimeSteps, DatesAtOneClockTime) {
  const OffsetDateTime noon = parse_clock_time("12:00", 60, "--at");
  const auto dates = instants_on_dates("03-21,06-21,2027-09-23,12-21", 2026, noon, "--dates");
  ASSERT_EQ(dates.size(), 4u);
  EXPECT_EQ(format_offset_date_time(dates[0]), "2026-03-21T12:00+01:00");
  EXPECT_EQ(format_offset_date_time(dates[2]), "2027-09-23T12:00+01:00");
  EXPECT_EQ(format_offset_date_time(dates[3]), "2026-12-21T12:00+01:00");
  EXPECT_EQ(parse_clock_time("07:30-04:00", 60, "--at").utc_offset_minutes, -240);
}

TEST(TimeSteps, StepsAndMistakes) {
  EXPECT_EQ(parse_step_seconds("10min", "--every"), 600);
  EXPECT_EQ(parse_step_seconds("1.5h", "--every"), 5400);
  EXPECT_EQ(parse_step_seconds("1d", "--every"), 86400);
  for (const char* bad : {"", "10", "0min", "-1h", "0.5s", "10 min", "nanh", "400d", "1e99s"})
    EXPECT_NE(testing::input_error_of([&] { parse_step_seconds(bad, "--every"); }).find("--every"), std::string::npos)
        << bad;
  EXPECT_NE(testing::input_error_of([&] {
              instants_every(at("2026-06-21T12:00Z"), at("2026-06-21T11:00Z"), 60, "--from/--to");
            }).find("comes before"),
            std::string::npos);
  EXPECT_NE(testing::input_error_of([&] {
              instants_every(at("2026-01-01T00:00Z"), at("2030-01-01T00:00Z"), 60, "--from/--to");
            }).find("more than"),
            std::string::npos);
  EXPECT_NE(testing::input_error_of([&] {
              instants_on_dates("02-30", 2026, parse_clock_time("12:00", 0, "a"), "--dates");
            }).find("--dates"),
            std::string::npos);
  EXPECT_NE(testing::input_error_of([&] {
              instants_on_dates("6-21", 2026, parse_clock_time("12:00", 0, "a"), "--dates");
            }).find("MM-DD"),
            std::string::npos);
  EXPECT_NE(testing::input_error_of([&] { parse_clock_time("25:00", 0, "--at"); }).find("--at"), std::string::npos);
}

}  // namespace
}  // namespace skylit
