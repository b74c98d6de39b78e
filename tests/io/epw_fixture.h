// A small EPW text of our own for the tests: the eight header lines and a few records
// whose fields are given by hand (EnergyPlus Auxiliary Programs, EPW data dictionary).
#pragma once

#include <string>
#include <vector>

namespace skylit::testing {

inline std::string epw_header(const std::string& location =
                                  "LOCATION,Testville,TS,XYZ,Own fixture,123456,48.50,"
                                  "-2.25,-3.5,812.0") {
  return location +
         "\nDESIGN CONDITIONS,0\nTYPICAL/EXTREME PERIODS,0\nGROUND TEMPERATURES,0\n"
         "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0\nCOMMENTS 1,fixture\nCOMMENTS 2,fixture\n"
         "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31\n";
}

// One record: month, day, hour and the 30 values after the data-source field, as
// text (fields 7 to 35). The defaults: a clear summer noon with plausible values.
struct EpwRecordFields {
  int year = 2001, month = 6, day = 21, hour = 13, minute = 60;
  std::string dry_bulb = "20.0", ghi = "800", dni = "700", dhi = "150", gh_lux = "90000", dn_lux = "70000",
              dh_lux = "18000", total_cover = "0", opaque_cover = "0", visibility = "30.0", ceiling = "77777",
              snow_depth = "0", albedo = "0.2";
};

inline std::string epw_record(const EpwRecordFields& f) {
  return std::to_string(f.year) + "," + std::to_string(f.month) + "," + std::to_string(f.day) + "," +
         std::to_string(f.hour) + "," + std::to_string(f.minute) + ",?9?9?9?9E0?9?9?9*9*9?9?9?9," + f.dry_bulb +
         ",10.0,50,101300,1300,1360,350," + f.ghi + "," + f.dni + "," + f.dhi + "," + f.gh_lux + "," + f.dn_lux + "," +
         f.dh_lux + ",9999,180,3.0," + f.total_cover + "," + f.opaque_cover + "," + f.visibility + "," + f.ceiling +
         ",9,999999999,15,0.100," + f.snow_depth + ",88," + f.albedo + ",0.0,0.0\n";
}

// The fixture: the header and records for 06-21 hours 12, 13, 14 and 06-22 hour 1.
inline std::string epw_fixture(const std::vector<EpwRecordFields>& extra = {}) {
  std::string text = epw_header();
  for (int hour : {12, 13, 14}) {
    EpwRecordFields f;
    f.hour = hour;
    text += epw_record(f);
  }
  EpwRecordFields night;
  night.day = 22, night.hour = 1, night.ghi = night.dni = night.dhi = "0";
  night.gh_lux = night.dn_lux = night.dh_lux = "0";
  text += epw_record(night);
  for (const EpwRecordFields& f : extra) text += epw_record(f);
  return text;
}

}  // namespace skylit::testing
