// Tabulated functions of wavelength (spectral data tables) and their averages over
// wavelength bins. Tables are read from the embedded data/ CSV files.
#pragma once

#include <string_view>
#include <vector>

namespace skylit {

// A function given at increasing abscissae, linear between them and zero outside.
struct Tabulated {
  std::vector<double> x;
  std::vector<double> y;

  double operator()(double at) const;
  // The exact mean of the piecewise-linear function over [a, b] (b > a).
  double average(double a, double b) const;
};

// Column `column` (1-based after the wavelength column 0) of the embedded CSV table
// `name` from data/, against its first column.
Tabulated embedded_table(std::string_view name, int column);

// Parses CSV text with one header row into columns of numbers; `source` names the
// text in error messages (InputError on a malformed line).
std::vector<std::vector<double>> parse_csv_columns(std::string_view text, std::string_view source);

}  // namespace skylit
