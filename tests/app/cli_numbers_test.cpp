// Numbers on the command line (issue 19, item 2, and the "CLI numbers" of its fuzz
// list): NaN passed CLI11's range checks and became an index into the atmosphere's
// tables (SIGSEGV), or was printed as "-nan" rows with exit status 0. Every numeric
// option of every subcommand is fed non-finite, overflowing and out-of-range values and
// seeded random out-of-range numbers: each must be refused as one line, exit status 2.
// `sun` checks its own (sun_command.cpp), `render`, `sweep` take --threads (an integer).
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "../test_support.h"

namespace skylit {
namespace {

using testing::run_skylit;

struct NumericOption {
  std::string command;  // with what else it requires
  std::string option;
  double lo, hi;  // the accepted range
};

std::vector<NumericOption> numeric_options() {
  std::vector<NumericOption> options;
  for (const std::string command : {"sky -o x.png", "spectrum"}) {
    const std::string with_altitude = command + " --sun-altitude 10";
    options.push_back({command, "--sun-altitude", -90, 90});
    options.push_back({with_altitude, "--sun-azimuth", -360, 360});
    options.push_back({with_altitude, "--aod550", 0, 10});
    options.push_back({with_altitude, "--angstrom", -1, 4});
    options.push_back({with_altitude, "--ozone-du", 0, 1000});
    options.push_back({with_altitude, "--ground-albedo", 0, 1});
    options.push_back({with_altitude, "--observer-altitude", 0, 90000});
  }
  options.push_back({"sky --sun-altitude 10 -o x.png", "--size", 8, 8192});
  const std::string sun = "sun --time 2026-06-21T12:00:00Z";
  options.push_back({sun + " --lon 0", "--lat", -90, 90});
  options.push_back({sun + " --lat 0", "--lon", -180, 180});
  const std::string site = sun + " --lat 0 --lon 0";
  options.push_back({site, "--elevation", -1000, 20000});
  options.push_back({site, "--pressure", 0, 2000});
  options.push_back({site, "--temperature", -100, 100});
  options.push_back({site, "--delta-t", -8000, 8000});
  options.push_back({"render x.json -o x.png", "--threads", 0, 1024});
  options.push_back({"sweep x.json --vary sun.altitude_deg=1 -o x.png", "--threads", 0, 1024});
  return options;
}

void expect_refused(const std::string& arguments) {
  const auto r = run_skylit(arguments);
  EXPECT_EQ(r.exit_status, 2) << arguments << ": " << r.output;
  EXPECT_EQ(r.output.rfind("skylit: ", 0), 0u) << arguments << ": " << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << arguments << ": " << r.output;
}

TEST(CliNumbers, NonFiniteAndOverflowingValuesAreRefusedByEveryNumericOption) {
  for (const NumericOption& o : numeric_options())
    for (const char* value : {"nan", "-nan", "inf", "-inf", "1e400"})
      expect_refused(o.command + " " + o.option + "=" + value);
}

TEST(CliNumbers, RandomOutOfRangeValuesAreRefused) {
  std::mt19937_64 random(19);  // seeded: the same values every run
  for (const NumericOption& o : numeric_options())
    for (int k = 0; k < 2; ++k) {
      // Just past either end, or far past it, with the exponent drawn at random.
      const double past = std::ldexp(1.0, static_cast<int>(random() % 40)) * (1.0 + 1e-9 * (random() % 1000));
      const double value = (random() % 2 == 0) ? o.hi + past : o.lo - past;
      expect_refused(o.command + " " + o.option + "=" + std::to_string(value));
    }
}

}  // namespace
}  // namespace skylit
