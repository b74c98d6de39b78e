// The program's numeric options (apps/skylit/number_checks.h): the bytes are the text
// given after an option such as `--sun-altitude`, parsed by CLI11 with the check every
// floating option uses. A value the check lets through must be a finite number inside
// the option's range (issue 19, item 2: `nan` passed CLI11's own Range and became an
// index into the atmosphere's tables); anything else must be refused as a parse error.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "../apps/skylit/number_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr double kMin = -90.0, kMax = 90.0;
  CLI::App app("fuzz");
  double value = 0;
  app.add_option("--value", value)->required()->check(skylit::cli::finite_range(kMin, kMax));
  // CLI11 takes the arguments last first.
  std::vector<std::string> args = {std::string(reinterpret_cast<const char*>(data), size), "--value"};
  try {
    app.parse(args);
  } catch (const CLI::ParseError&) {
    return 0;  // refused: the program prints one line and exits 2
  }
  if (!std::isfinite(value) || value < kMin || value > kMax) abort();
  return 0;
}
