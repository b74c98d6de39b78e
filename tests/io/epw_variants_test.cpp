// Real EPW files differ from the data dictionary's example in ways the reader must take
// (io/weather/epw_reader.h, docs/weather.md "Files in the wild"): line endings, a byte
// order mark, Latin-1 station names, minute 0 or 60, trailing commas and blank lines,
// leap years, data that does not start on January 1, half-hour time zones on both
// sides of Greenwich, the southern hemisphere and the polar day and night. Each
// fixture is written here by hand; none is copied from a real file.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../test_support.h"
#include "epw_fixture.h"
#include "skylit/io/weather/epw_reader.h"
#include "skylit/io/weather/weather_conditions.h"
#include "skylit/sun/solar_position.h"

namespace skylit {
namespace {

using testing::epw_header;
using testing::epw_record;
using testing::EpwRecordFields;
using testing::input_error_of;

std::string records(std::vector<EpwRecordFields> fields) {
  std::string text;
  for (const EpwRecordFields& f : fields) text += epw_record(f);
  return text;
}

EpwRecordFields at(int month, int day, int hour, int year = 2001, int minute = 60) {
  EpwRecordFields f;
  f.year = year, f.month = month, f.day = day, f.hour = hour, f.minute = minute;
  return f;
}

std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST(EpwVariants, LineEndingsByteOrderMarkTrailingCommasAndBlankLinesReadAlike) {
  const std::string plain = epw_header() + records({at(6, 21, 12), at(6, 21, 13)});
  const EpwFile reference = parse_epw(plain, "plain.epw");
  const std::string trailing_commas = replaced_all(plain, "0.0,0.0\n", "0.0,0.0,,\n");
  for (const auto& [name, text] :
       std::vector<std::pair<std::string, std::string>>{{"crlf.epw", replaced_all(plain, "\n", "\r\n")},
                                                        {"cr.epw", replaced_all(plain, "\n", "\r")},
                                                        {"bom.epw", "\xEF\xBB\xBF" + plain},
                                                        {"blank-lines.epw", plain + "\n  \n\r\n\n"},
                                                        {"trailing-commas.epw", trailing_commas}}) {
    SCOPED_TRACE(name);
    const EpwFile f = parse_epw(text, name);
    EXPECT_EQ(f.location.city, "Testville");
    EXPECT_DOUBLE_EQ(f.location.elevation_m, 812.0);  // the last header field, before the line's end
    ASSERT_EQ(f.hours.size(), 2u);
    EXPECT_EQ(f.hours[1].line, 10);  // lines are counted alike
    EXPECT_DOUBLE_EQ(*f.hours[1].albedo, *reference.hours[1].albedo);
    EXPECT_EQ(f.hours[1].missing, reference.hours[1].missing);
  }
  // Commas past the 35 fields are taken only when nothing stands after them.
  const std::string error =
      input_error_of([&] { parse_epw(replaced_all(plain, "0.0,0.0\n", "0.0,0.0,,7\n"), "extra.epw"); });
  EXPECT_NE(error.find("extra.epw:9: a data record has 37 fields"), std::string::npos) << error;
}

TEST(EpwVariants, StationNamesInUtf8OrLatin1BecomeUtf8) {
  const EpwFile utf8 =
      parse_epw(epw_header("LOCATION,Z\xC3\xBCrich-Kloten,ZH,CHE,Own fixture,066700,47.48,8.54,1.0,432.0") +
                    records({at(6, 21, 13)}),
                "utf8.epw");
  EXPECT_EQ(utf8.location.city, "Z\xC3\xBCrich-Kloten");
  // ISO 8859-1, as older tools write it: ü is the single byte 0xFC.
  const EpwFile latin1 = parse_epw(
      epw_header("LOCATION,Z\xFCrich-Kloten,ZH,CHE,Own fixture,066700,47.48,8.54,1.0,432.0") + records({at(6, 21, 13)}),
      "latin1.epw");
  EXPECT_EQ(latin1.location.city, "Z\xC3\xBCrich-Kloten");
  EXPECT_EQ(latin1.location.country, "CHE");
}

TEST(EpwVariants, MinuteZeroAndSixtyNameTheSameHour) {
  const EpwFile zero = parse_epw(epw_header() + records({at(6, 21, 12, 2001, 0), at(6, 21, 13, 2001, 0)}), "tmyx.epw");
  const EpwFile sixty = parse_epw(epw_header() + records({at(6, 21, 12), at(6, 21, 13)}), "energyplus.epw");
  EXPECT_EQ(zero.hours[1].minute, 0);
  EXPECT_EQ(epw_hour_containing(zero, 6, 21, 12, 30, "t").line, epw_hour_containing(sixty, 6, 21, 12, 30, "t").line);
  EXPECT_EQ(epw_hour_containing(zero, 6, 21, 12, 30, "t").hour, 13);
}

TEST(EpwVariants, LeapYearFilesAndDataThatStartsMidYear) {
  // An actual-year file of 2020: 02-29 exists, and 03-01 00:00 closes its hour 24.
  const EpwFile leap = parse_epw(
      epw_header() + records({at(2, 28, 24, 2020), at(2, 29, 12, 2020), at(2, 29, 24, 2020), at(3, 1, 1, 2020)}),
      "leap.epw");
  EXPECT_EQ(epw_hour_containing(leap, 2, 29, 11, 30, "t").line, 10);
  EXPECT_EQ(epw_hour_containing(leap, 3, 1, 0, 0, "t").line, 11);
  Scene scene;
  apply_weather_hour(leap, leap.hours[1], scene);
  EXPECT_EQ(scene.weather->sun_time, "2020-02-29T11:30-03:30");
  // A file whose data period begins on 07-01: its first record has no day before it in
  // the file, so 07-01 00:00 is not there (rather than the file's last record).
  std::string midyear = epw_header();
  midyear.replace(midyear.find(" 1/ 1,12/31"), 11, " 7/ 1, 7/ 2");
  const EpwFile july = parse_epw(midyear + records({at(7, 1, 1), at(7, 1, 2), at(7, 2, 24)}), "july.epw");
  EXPECT_EQ(epw_hour_containing(july, 7, 1, 1, 30, "t").line, 10);
  const std::string error = input_error_of([&] { epw_hour_containing(july, 7, 1, 0, 0, "scene.json: weather.hour"); });
  EXPECT_NE(error.find("july.epw has no record for 07-01T00:00 (hour 24 of the day before"), std::string::npos)
      << error;
  // A typical year wraps: 01-01 00:00 is the 12-31 hour 24 at the file's end.
  const EpwFile year = parse_epw(epw_header() + records({at(1, 1, 1), at(12, 31, 24)}), "year.epw");
  EXPECT_EQ(epw_hour_containing(year, 1, 1, 0, 0, "t").line, 10);
}

// The sun of an hour in a file whose standard time is `zone`: the hour's middle, at
// the site, by the SPA the scene uses.
void expect_sun_at_the_hours_middle(const std::string& location, const EpwRecordFields& record,
                                    const std::string& expected_time) {
  const EpwFile file = parse_epw(epw_header(location) + records({record}), "site.epw");
  Scene scene;
  apply_weather_hour(file, file.hours[0], scene);
  ASSERT_TRUE(scene.weather);
  EXPECT_EQ(scene.weather->sun_time, expected_time);
  SpaOptions air;
  air.pressure_mbar = 1013, air.temperature_c = 20;  // the fixture's record
  const SiteLocation site{file.location.latitude_deg, file.location.longitude_deg, file.location.elevation_m};
  const SolarPosition sun = solar_position(site, parse_offset_date_time(expected_time, "t"), air);
  EXPECT_NEAR(scene.sun.altitude_deg, sun.altitude_deg, 1e-9);
  EXPECT_NEAR(scene.sun.azimuth_deg, sun.azimuth_deg, 1e-9);
}

TEST(EpwVariants, HalfHourZonesEastAndWest) {
  // India (UTC+5:30) and Newfoundland (UTC−3:30): hour 13 is 12:00–13:00 local standard
  // time; near noon the sun stands high (New Delhi) and moderately high (St. John's).
  expect_sun_at_the_hours_middle("LOCATION,New Delhi,DL,IND,Own fixture,421820,28.58,77.20,5.5,216.0", at(6, 21, 13),
                                 "2001-06-21T12:30+05:30");
  expect_sun_at_the_hours_middle("LOCATION,St. John's,NL,CAN,Own fixture,718010,47.62,-52.75,-3.5,140.0", at(6, 21, 13),
                                 "2001-06-21T12:30-03:30");
}

TEST(EpwVariants, SouthernHemisphereAndPolarDayAndNight) {
  // Sydney in June: the noon sun stands in the north, low (at most 90 − 33.95 − 23.44).
  const std::string sydney = "LOCATION,Sydney,NSW,AUS,Own fixture,947670,-33.95,151.18,10.0,3.0";
  expect_sun_at_the_hours_middle(sydney, at(6, 21, 13), "2001-06-21T12:30+10:00");
  const EpwFile south = parse_epw(epw_header(sydney) + records({at(6, 21, 13)}), "sydney.epw");
  Scene winter;
  apply_weather_hour(south, south.hours[0], winter);
  EXPECT_LT(winter.sun.altitude_deg, 90 - 33.95 - 23.4);
  EXPECT_GT(winter.sun.altitude_deg, 25.0);
  EXPECT_LT(std::min(winter.sun.azimuth_deg, 360 - winter.sun.azimuth_deg), 20.0);  // north
  EXPECT_GT(winter.atmosphere.aerosol.aod_550, 0.0);                                // the beam was fitted

  // Tromsø (69.68° N): the midnight sun in June, no sun at noon in December.
  const std::string tromso = "LOCATION,Troms\xC3\xB8,TR,NOR,Own fixture,010250,69.68,18.92,1.0,100.0";
  EpwRecordFields midnight = at(6, 21, 1);
  midnight.dn_lux = "5000", midnight.dni = "50", midnight.gh_lux = "4000", midnight.dh_lux = "3700";
  EpwRecordFields polar_noon = at(12, 21, 13);
  polar_noon.dn_lux = polar_noon.gh_lux = polar_noon.dh_lux = polar_noon.dni = polar_noon.ghi = polar_noon.dhi = "0";
  const EpwFile north = parse_epw(epw_header(tromso) + records({midnight, polar_noon}), "tromso.epw");
  Scene day, night;
  apply_weather_hour(north, north.hours[0], day);
  apply_weather_hour(north, north.hours[1], night);
  EXPECT_GT(day.sun.altitude_deg, 0.0);  // 00:30 at the summer solstice: the sun is up
  EXPECT_LT(day.sun.altitude_deg, 5.0);
  EXPECT_GT(day.atmosphere.aerosol.aod_550, 0.0);
  EXPECT_TRUE(std::isfinite(day.atmosphere.aerosol.aod_550));
  EXPECT_LT(night.sun.altitude_deg, 0.0);  // 12:30 at the winter solstice: below the horizon
  EXPECT_FALSE(night.atmosphere.cie_sky);  // no overcast sky stands in for a sun that is down
}

}  // namespace
}  // namespace skylit
