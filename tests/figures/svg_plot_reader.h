// Reads a plot written by render_plot_svg (plot_svg.cpp) back into numbers, for tests
// that check a figure against the data it was drawn from: the axes from their grid
// lines and tick labels, each series' points (polylines and lone dots) mapped back to
// data units, and its label from the legend. The grid lines lie on whole pixels (their
// ticks are floored to the pixel), so a value read back is good to about one pixel of
// its axis: `x_per_pixel` and `y_per_pixel` give that unit.
#pragma once

#include <map>
#include <regex>
#include <string>
#include <vector>

namespace skylit::testing {

struct SvgPlotSeries {
  std::string label;
  std::vector<std::pair<double, double>> points;  // (x, y) in data units, in drawing order
};

struct SvgPlot {
  std::vector<SvgPlotSeries> series;  // in drawing order
  double x_per_pixel = 0, y_per_pixel = 0;
};

namespace svg_plot_detail {

inline std::vector<std::smatch> matches(const std::string& text, const std::regex& pattern) {
  return {std::sregex_iterator(text.begin(), text.end(), pattern), std::sregex_iterator()};
}

inline bool parses_as_number(const std::string& text, double& value) {
  try {
    std::size_t used = 0;
    value = std::stod(text, &used);
    return used == text.size();
  } catch (const std::exception&) {
    return false;
  }
}

// The linear map from pixels to values through the first and last (pixel, value) pair.
struct Axis {
  double pixel0 = 0, value0 = 0, per_pixel = 0;
  double operator()(double pixel) const { return value0 + (pixel - pixel0) * per_pixel; }
};

inline Axis axis_through(const std::vector<double>& pixels, const std::vector<double>& values) {
  if (pixels.size() < 2 || pixels.size() != values.size()) return {};
  return {pixels.front(), values.front(), (values.back() - values.front()) / (pixels.back() - pixels.front())};
}

}  // namespace svg_plot_detail

inline SvgPlot read_svg_plot(const std::string& svg) {
  using namespace svg_plot_detail;
  SvgPlot plot;
  // Grid lines: vertical ones at the x ticks, then horizontal ones at the left y ticks.
  const std::size_t grid_at = svg.find("<g stroke=\"#e1e1e1\">");
  const std::string grid = svg.substr(grid_at, svg.find("</g>", grid_at) - grid_at);
  const std::regex line_pattern(R"re(<line x1="([-\d.]+)" y1="([-\d.]+)" x2="([-\d.]+)" y2="([-\d.]+)"/>)re");
  std::vector<double> x_pixels, y_pixels;
  for (const std::smatch& m : matches(grid, line_pattern)) {
    if (m[1] == m[3]) x_pixels.push_back(std::stod(m[1]));
    if (m[2] == m[4]) y_pixels.push_back(std::stod(m[2]));
  }
  // Tick labels in the same order: numbers centred under the x axis, right-aligned left of the y axis.
  std::vector<double> x_values, y_values;
  const std::regex text_pattern(R"re(<text x="[-\d.]+" y="[-\d.]+" text-anchor="(\w+)"[^>]*>([^<]*)</text>)re");
  for (const std::smatch& m : matches(svg, text_pattern)) {
    double value = 0;
    if (!parses_as_number(m[2], value)) continue;
    if (m[1] == "middle" && x_values.size() < x_pixels.size()) x_values.push_back(value);
    if (m[1] == "end" && y_values.size() < y_pixels.size()) y_values.push_back(value);
  }
  const Axis x = axis_through(x_pixels, x_values), y = axis_through(y_pixels, y_values);
  plot.x_per_pixel = std::abs(x.per_pixel), plot.y_per_pixel = std::abs(y.per_pixel);

  // Legend: a swatch line in the series' colour, then its text.
  std::map<std::string, std::string> label_of;
  const std::regex legend_pattern(
      R"re(<line [^>]*stroke="(#[0-9a-f]{6})" stroke-width="[\d.]+"/>\n<text [^>]*>([^<]*)</text>)re");
  for (const std::smatch& m : matches(svg, legend_pattern)) label_of[m[1]] = m[2];

  // Series: one <g stroke="#colour"> each inside the clipped group.
  const std::size_t series_at = svg.find("<g clip-path=\"url(#plot-area)\"");
  const std::string drawn = svg.substr(series_at, svg.find("</g>\n</g>", series_at) + 4 - series_at);
  const std::regex group_pattern(R"re(<g stroke="(#[0-9a-f]{6})">\n([\s\S]*?)</g>)re");
  const std::regex point_pattern(R"re(([-\d.]+),([-\d.]+))re");
  const std::regex dot_pattern(R"re(<circle cx="([-\d.]+)" cy="([-\d.]+)")re");
  for (const std::smatch& g : matches(drawn, group_pattern)) {
    SvgPlotSeries series;
    series.label = label_of[g[1]];
    const std::string body = g[2];
    for (const std::smatch& p : matches(body, point_pattern))
      series.points.emplace_back(x(std::stod(p[1])), y(std::stod(p[2])));
    for (const std::smatch& d : matches(body, dot_pattern))
      series.points.emplace_back(x(std::stod(d[1])), y(std::stod(d[2])));
    plot.series.push_back(std::move(series));
  }
  return plot;
}

}  // namespace skylit::testing
