// The EPW reader (io/weather/epw_reader.h): the LOCATION header, the records, EPW's
// missing codes, the hour-ending convention, and one located error for a bad file.
#include "skylit/io/weather/epw_reader.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "../test_support.h"
#include "epw_fixture.h"

namespace skylit {
namespace {

using testing::epw_fixture;
using testing::epw_header;
using testing::epw_record;
using testing::EpwRecordFields;
using testing::input_error_of;

bool names(const EpwHour& h, const std::string& field) {
  return std::find(h.missing.begin(), h.missing.end(), field) != h.missing.end();
}

TEST(EpwReader, ReadsTheLocationLine) {
  const EpwFile f = parse_epw(epw_fixture(), "fixture.epw");
  EXPECT_EQ(f.location.city, "Testville");
  EXPECT_EQ(f.location.country, "XYZ");
  EXPECT_EQ(f.location.wmo_station, "123456");
  EXPECT_DOUBLE_EQ(f.location.latitude_deg, 48.5);
  EXPECT_DOUBLE_EQ(f.location.longitude_deg, -2.25);
  EXPECT_DOUBLE_EQ(f.location.time_zone_h, -3.5);  // half-hour zones exist (Newfoundland)
  EXPECT_DOUBLE_EQ(f.location.elevation_m, 812.0);
  ASSERT_EQ(f.hours.size(), 4u);
  EXPECT_EQ(f.hours[1].line, 10);  // eight header lines, then hours 12 and 13
  EXPECT_EQ(f.hours[1].hour, 13);
  EXPECT_DOUBLE_EQ(*f.hours[1].direct_normal_lux, 70000);
  EXPECT_DOUBLE_EQ(*f.hours[1].visibility_km, 30);
  EXPECT_DOUBLE_EQ(*f.hours[1].albedo, 0.2);
  // Zenith luminance is 9999 (missing) in every fixture record, and named.
  EXPECT_FALSE(f.hours[1].zenith_luminance_cd_m2);
  EXPECT_TRUE(names(f.hours[1], "zenith luminance"));
}

TEST(EpwReader, MissingCodesAndOutOfRangeValuesBecomeNamedGaps) {
  EpwRecordFields f;
  f.day = 23, f.ghi = "9999", f.dn_lux = "999999", f.visibility = "9999", f.snow_depth = "999", f.opaque_cover = "99",
  f.dry_bulb = "99.9", f.ceiling = "99999", f.total_cover = "12" /* over 10 tenths */;
  const EpwFile file = parse_epw(epw_fixture({f}), "fixture.epw");
  const EpwHour& h = file.hours.back();
  EXPECT_FALSE(h.global_horizontal_w_m2);
  EXPECT_FALSE(h.direct_normal_lux);
  EXPECT_FALSE(h.visibility_km);
  EXPECT_FALSE(h.snow_depth_cm);
  EXPECT_FALSE(h.opaque_sky_cover_tenths);
  EXPECT_FALSE(h.total_sky_cover_tenths);
  EXPECT_FALSE(h.dry_bulb_c);
  EXPECT_FALSE(h.ceiling_height_m);
  for (const char* name : {"global horizontal radiation", "direct normal illuminance", "visibility", "snow depth",
                           "opaque sky cover", "total sky cover", "dry bulb temperature", "ceiling height"})
    EXPECT_TRUE(names(h, name)) << name;
  // The fields that were given stay.
  EXPECT_DOUBLE_EQ(*h.direct_normal_w_m2, 700);
  EXPECT_FALSE(names(h, "direct normal radiation"));
}

TEST(EpwReader, AnHourIsTheOneEndingAtTheNextWholeHour) {
  const EpwFile f = parse_epw(epw_fixture(), "fixture.epw");
  // Hour 13 is 12:00–13:00: 12:30 and 13:00 lie in it, 13:01 does not.
  EXPECT_EQ(epw_hour_containing(f, 6, 21, 12, 30, "t").hour, 13);
  EXPECT_EQ(epw_hour_containing(f, 6, 21, 13, 0, "t").hour, 13);
  EXPECT_EQ(epw_hour_containing(f, 6, 21, 13, 1, "t").hour, 14);
  EXPECT_EQ(epw_hour_containing(f, 6, 21, 11, 59, "t").hour, 12);
  // Midnight closes the previous day's hour 24, which this fixture lacks: the record
  // before 06-22 hour 1 is 06-21 hour 14, not the hour that ends at 00:00 (the files
  // that have it: tests/io/epw_variants_test.cpp).
  EXPECT_NE(input_error_of([&] {
              epw_hour_containing(f, 6, 22, 0, 0, "t");
            }).find("has no record for 06-22T00:00 (hour 24 of the day before"),
            std::string::npos);
  const std::string error = input_error_of([&] { epw_hour_containing(f, 7, 1, 12, 0, "scene.json: weather.hour"); });
  EXPECT_NE(error.find("scene.json: weather.hour: fixture.epw has no record for 07-01T12:00"), std::string::npos)
      << error;
}

TEST(EpwReader, AMalformedFileIsOneLocatedError) {
  const auto error_of = [](const std::string& text) { return input_error_of([&] { parse_epw(text, "bad.epw"); }); };
  EpwRecordFields f;
  f.dry_bulb = "warm";
  EXPECT_EQ(error_of(epw_header() + epw_record(f)),
            "bad.epw:9: field 7 (dry bulb temperature): expected a number, found 'warm'");
  f = {};
  f.month = 13;
  EXPECT_EQ(error_of(epw_header() + epw_record(f)),
            "bad.epw:9: field 2 (month): expected a whole number from 1 to 12, found '13'");
  f = {};
  f.month = 4, f.day = 31;
  EXPECT_NE(error_of(epw_header() + epw_record(f)).find("bad.epw:9: field 3 (day)"), std::string::npos);
  EXPECT_NE(error_of(epw_header() + "2001,1,1,1,60,x,1,2\n").find("bad.epw:9: a data record has 8 fields"),
            std::string::npos);
  EXPECT_NE(error_of("DESIGN CONDITIONS,0\n").find("bad.epw:1: an EPW file begins with its LOCATION line"),
            std::string::npos);
  EXPECT_EQ(error_of(epw_header("LOCATION,X,-,Y,src,1,95.0,0,0,0")),
            "bad.epw:1: field 7 (latitude): must lie within -90 to 90");
  EXPECT_NE(error_of(epw_header()).find("no hourly records"), std::string::npos);
  // Without its DATA PERIODS line the header runs into the records: said at the first
  // record (line 8 here), not at the file's last line.
  std::string header = epw_header();
  const size_t periods = header.find("DATA PERIODS");
  ASSERT_NE(periods, std::string::npos);
  header.erase(periods, header.find('\n', periods) + 1 - periods);
  EXPECT_EQ(error_of(header + epw_record({}) + epw_record({})),
            "bad.epw:8: a record before the DATA PERIODS line, which ends the header (is it missing?)");
  EXPECT_NE(error_of("").find("empty file"), std::string::npos);
}

// The shared weather file (never copied into the project): ../shared/data beside the
// source tree. A clean CI machine has none, and skips.
TEST(EpwReader, ReadsTheSharedAmsterdamFile) {
  const std::filesystem::path file =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/NLD_Amsterdam062400_IWEC.epw";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file << " (the shared data is not on this machine)";
  const EpwFile f = read_epw(file);
  EXPECT_EQ(f.location.city, "AMSTERDAM");
  EXPECT_DOUBLE_EQ(f.location.latitude_deg, 52.30);
  EXPECT_DOUBLE_EQ(f.location.longitude_deg, 4.77);
  EXPECT_DOUBLE_EQ(f.location.time_zone_h, 1.0);
  EXPECT_DOUBLE_EQ(f.location.elevation_m, -2.0);
  ASSERT_EQ(f.hours.size(), 8760u);
  const EpwHour& h = epw_hour_containing(f, 6, 21, 8, 0, "t");  // line 4120: 07:00–08:00
  EXPECT_EQ(h.line, 4120);
  EXPECT_DOUBLE_EQ(*h.direct_normal_w_m2, 280);
  EXPECT_DOUBLE_EQ(*h.direct_normal_lux, 26000);
  EXPECT_DOUBLE_EQ(*h.opaque_sky_cover_tenths, 5);
}

}  // namespace
}  // namespace skylit
