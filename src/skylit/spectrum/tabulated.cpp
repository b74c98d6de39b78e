#include "skylit/spectrum/tabulated.h"

#include <algorithm>
#include <charconv>
#include <string>

#include "skylit/core/embedded_data.h"
#include "skylit/core/error.h"
#include "skylit/core/text_file.h"

namespace skylit {

double Tabulated::operator()(double at) const {
  if (x.empty() || at < x.front() || at > x.back()) return 0.0;
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  if (it == x.end()) return y.back();
  const size_t i = static_cast<size_t>(it - x.begin());
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

double Tabulated::average(double a, double b) const {
  // Integrate the linear pieces that overlap [a, b] exactly (trapezoids of the
  // clipped pieces), so bin averages are independent of the table's step.
  double integral = 0.0;
  for (size_t i = 1; i < x.size(); ++i) {
    const double lo = std::max(a, x[i - 1]), hi = std::min(b, x[i]);
    if (hi <= lo) continue;
    integral += 0.5 * ((*this)(lo) + (*this)(hi)) * (hi - lo);
  }
  return integral / (b - a);
}

std::vector<std::vector<double>> parse_csv_columns(std::string_view text, std::string_view source) {
  std::vector<std::vector<double>> columns;
  size_t line_start = 0;
  int line_number = 0;
  while (line_start < text.size()) {
    size_t line_end = text.find('\n', line_start);
    if (line_end == std::string_view::npos) line_end = text.size();
    std::string_view line = text.substr(line_start, line_end - line_start);
    line_start = line_end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line_number == 1 || line.empty()) continue;  // header row, blank lines
    // The first data row sets the number of columns; every later row must have as many.
    const size_t fields = 1 + static_cast<size_t>(std::count(line.begin(), line.end(), ','));
    if (!columns.empty() && fields != columns.size())
      throw InputError(std::string(source) + ":" + std::to_string(line_number) + ": expected " +
                       std::to_string(columns.size()) + " columns, found " + std::to_string(fields));
    if (columns.empty()) columns.resize(fields);
    size_t column = 0, field_start = 0;
    while (field_start <= line.size()) {
      size_t field_end = line.find(',', field_start);
      if (field_end == std::string_view::npos) field_end = line.size();
      const std::string_view field = line.substr(field_start, field_end - field_start);
      double value = 0;
      const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
      if (ec != std::errc() || end != field.data() + field.size())
        throw InputError(std::string(source) + ":" + std::to_string(line_number) + ": expected a number, found " +
                         quote_excerpt(field));
      columns[column].push_back(value);
      ++column;
      field_start = field_end + 1;
    }
  }
  return columns;
}

Tabulated embedded_table(std::string_view name, int column) {
  auto columns = parse_csv_columns(data::embedded_file(name), name);
  return {std::move(columns.at(0)), std::move(columns.at(static_cast<size_t>(column)))};
}

}  // namespace skylit
