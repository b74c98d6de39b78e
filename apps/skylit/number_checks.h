// A check for the program's numeric options. CLI11's Range compares with < and >, and
// every comparison with NaN is false, so `--sun-altitude nan` passed it and became an
// index into the atmosphere's tables (issue 19, item 2). This one refuses what is not
// a finite number before the range.
#pragma once

#include <cmath>
#include <string>

#include <CLI/CLI.hpp>

namespace skylit::cli {

inline CLI::Validator finite_range(double min, double max) {
  const CLI::Range range(min, max);
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "Value " + text + " is not a number";
        if (!std::isfinite(value)) return "Value " + text + " is not a finite number";
        return range(text);
      },
      range.get_description());
}

}  // namespace skylit::cli
