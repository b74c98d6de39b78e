// ISO 8601 date-times with a UTC offset, and their Julian Day (UT). Known Julian Days
// are from Meeus, "Astronomical Algorithms" (2nd ed.), ch. 7.
#include "skylit/sun/time.h"

#include <gtest/gtest.h>

#include "../test_support.h"

#include <string>

#include "skylit/core/error.h"

namespace skylit {
namespace {

constexpr const char* kWhere = "scene.json: time";

OffsetDateTime parse(const std::string& text) { return parse_offset_date_time(text, kWhere); }

// The message of the InputError that parsing `text` throws ("" if it does not throw).
std::string error_of(const std::string& text) {
  return testing::input_error_of([&] { parse(text); });
}

TEST(TimeParsing, ReadsEveryFieldAndTheOffset) {
  const OffsetDateTime t = parse("2026-06-21T07:05:09+09:00");
  EXPECT_EQ(t.year, 2026);
  EXPECT_EQ(t.month, 6);
  EXPECT_EQ(t.day, 21);
  EXPECT_EQ(t.hour, 7);
  EXPECT_EQ(t.minute, 5);
  EXPECT_DOUBLE_EQ(t.second, 9);
  EXPECT_EQ(t.utc_offset_minutes, 540);
}

TEST(TimeParsing, AcceptsEveryOffsetForm) {
  EXPECT_EQ(parse("2026-06-21T07:00:00Z").utc_offset_minutes, 0);
  EXPECT_EQ(parse("2026-06-21T07:00:00z").utc_offset_minutes, 0);
  EXPECT_EQ(parse("2026-06-21T07:00:00-07:00").utc_offset_minutes, -420);
  EXPECT_EQ(parse("2026-06-21T07:00:00+0530").utc_offset_minutes, 330);
  EXPECT_EQ(parse("2026-06-21T07:00:00-0330").utc_offset_minutes, -210);
  EXPECT_EQ(parse("2026-06-21T07:00:00+01").utc_offset_minutes, 60);
  EXPECT_EQ(parse("2026-06-21T07:00:00+00:00").utc_offset_minutes, 0);
}

TEST(TimeParsing, SecondsAreOptionalAndMayHaveAFraction) {
  EXPECT_DOUBLE_EQ(parse("2026-06-21T07:00Z").second, 0);
  EXPECT_DOUBLE_EQ(parse("2026-06-21T07:00:30.25Z").second, 30.25);
  EXPECT_DOUBLE_EQ(parse("2026-06-21T07:00:30,5Z").second, 30.5);
  EXPECT_DOUBLE_EQ(parse("2016-12-31T23:59:60Z").second, 60);  // a leap second
  EXPECT_EQ(parse("2026-06-21 07:00:00Z").hour, 7);            // RFC 3339 allows a space
}

TEST(TimeParsing, LeapDaysOnlyInLeapYears) {
  EXPECT_EQ(parse("2024-02-29T12:00:00Z").day, 29);
  EXPECT_EQ(parse("2000-02-29T12:00:00Z").day, 29);
  const std::string message = error_of("2026-02-29T12:00:00Z");
  EXPECT_EQ(message, "scene.json: time: 2026-02-29 is not a date: February 2026 has 28 days");
  EXPECT_NE(error_of("1900-02-29T12:00:00Z"), "");  // divisible by 100, not by 400
  EXPECT_NE(error_of("2026-04-31T12:00:00Z"), "");
  EXPECT_NE(error_of("2026-01-00T12:00:00Z"), "");
}

TEST(TimeParsing, MissingOffsetIsRefusedAsAmbiguous) {
  const std::string message = error_of("2026-06-21T07:00:00");
  EXPECT_EQ(message.rfind("scene.json: time: ", 0), 0u) << message;
  EXPECT_NE(message.find("no UTC offset"), std::string::npos) << message;
  EXPECT_NE(message.find("ambiguous"), std::string::npos) << message;
  EXPECT_NE(message.find("2026-06-21T07:00:00+09:00"), std::string::npos) << message;
}

TEST(TimeParsing, OutOfRangeFieldsSayWhatIsExpected) {
  EXPECT_NE(error_of("2026-13-01T07:00:00Z").find("month 13"), std::string::npos);
  EXPECT_NE(error_of("2026-06-21T24:00:00Z").find("hour 24"), std::string::npos);
  EXPECT_NE(error_of("2026-06-21T07:60:00Z").find("minute 60"), std::string::npos);
  EXPECT_NE(error_of("2026-06-21T07:00:61Z").find("below 61"), std::string::npos);
  EXPECT_NE(error_of("2026-06-21T07:00:00+19:00").find("offset"), std::string::npos);
  EXPECT_NE(error_of("2026-06-21T07:00:00+09:60").find("offset"), std::string::npos);
}

TEST(TimeParsing, MalformedTextIsAnInputErrorNamingThePlace) {
  for (const char* text :
       {"", "tomorrow", "2026-6-21T07:00Z", "2026-06-21", "2026-06-21T7:00Z", "2026-06-21T07Z", "2026-06-21T07:00:00.Z",
        "2026-06-21T07:00:00+9", "2026-06-21T07:00:00Zjunk", "2026/06/21T07:00:00Z", "20260621T070000Z"}) {
    const std::string message = error_of(text);
    EXPECT_EQ(message.rfind("scene.json: time: ", 0), 0u) << text << " -> " << message;
  }
  EXPECT_NE(error_of("2026-06-21").find("only a date"), std::string::npos);
  EXPECT_NE(error_of("tomorrow").find("expected an ISO 8601 date-time"), std::string::npos);
}

TEST(TimeJulianDay, J2000IsNoonOnTheFirstOf2000) {
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("2000-01-01T12:00:00Z")), 2451545.0);
}

TEST(TimeJulianDay, KnownDates) {
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("1970-01-01T00:00:00Z")), 2440587.5);
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("1987-01-27T00:00:00Z")), 2446822.5);  // Meeus, ch. 7
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("1988-06-19T12:00:00Z")), 2447332.0);
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("1900-01-01T00:00:00Z")), 2415020.5);
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("1600-12-31T00:00:00Z")), 2305812.5);
  EXPECT_NEAR(julian_day_ut(parse("1957-10-04T19:26:24Z")), 2436116.31, 1e-9);  // Sputnik 1, Meeus Ex. 7.a
  // Proleptic Gregorian: 0001-01-01 is 1721425.5, and year 0 is a leap year.
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("0001-01-01T00:00:00Z")), 1721425.5);
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("0000-01-01T00:00:00Z")), 1721059.5);
}

TEST(TimeJulianDay, OffsetIsSubtractedToGetUniversalTime) {
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("2026-06-21T07:00:00+09:00")), julian_day_ut(parse("2026-06-20T22:00:00Z")));
  EXPECT_DOUBLE_EQ(julian_day_ut(parse("2026-12-31T20:30:00-0530")), julian_day_ut(parse("2027-01-01T02:00:00Z")));
  // The NREL SPA example: 2003-10-17 12:30:30 at UTC−7 (Reda & Andreas, Table A5.1).
  EXPECT_NEAR(julian_day_ut(parse("2003-10-17T12:30:30-07:00")), 2452930.312847, 5e-7);
}

TEST(TimeJulianDay, KeepsSubSecondPrecision) {
  const double a = julian_day_ut(parse("2026-06-21T07:00:00.000Z"));
  const double b = julian_day_ut(parse("2026-06-21T07:00:00.100Z"));
  EXPECT_NEAR((b - a) * 86400.0, 0.1, 1e-4);
}

TEST(TimeCalendar, LeapYearsAndMonthLengths) {
  EXPECT_TRUE(is_leap_year(2024));
  EXPECT_TRUE(is_leap_year(2000));
  EXPECT_FALSE(is_leap_year(1900));
  EXPECT_FALSE(is_leap_year(2026));
  EXPECT_EQ(days_in_month(2024, 2), 29);
  EXPECT_EQ(days_in_month(2026, 2), 28);
  EXPECT_EQ(days_in_month(2026, 4), 30);
  EXPECT_EQ(days_in_month(2026, 12), 31);
}

}  // namespace
}  // namespace skylit
