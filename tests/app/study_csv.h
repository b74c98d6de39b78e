// Shared by the tests of `animate --stats` and `sweep --stats`: the CSVs read into
// cells, and the statistics plot checked against the statistics CSV it was drawn from.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../figures/svg_plot_reader.h"
#include "../test_support.h"
#include "skylit/sun/time.h"
#include "skylit/sun/time_steps.h"

namespace skylit::testing {

// A CSV without quoted cells, split on commas.
inline std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    rows.emplace_back();
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) rows.back().push_back(cell);
  }
  return rows;
}

// The statistics plot shows the CSV's numbers: each object's and the sky's mean
// luminance at its frame's time, read back from the SVG within 2 pixels of each axis
// (the grid lines the reader maps through lie on whole pixels). `group_column` is the
// CSV's group column, if any, whose value joins the series' label as the plot writes it.
// The study must span at most three days (the plot's x axis is then in hours).
inline void expect_plot_shows_csv(const std::vector<std::vector<std::string>>& csv, const std::filesystem::path& svg,
                                  std::optional<std::size_t> group_column) {
  const std::size_t at = group_column ? 1 : 0;  // the columns after the group shift by one
  std::map<std::string, std::vector<std::pair<double, double>>> expected;
  std::optional<OffsetDateTime> first;
  for (std::size_t i = 1; i < csv.size(); ++i) {
    const std::vector<std::string>& row = csv[i];
    const std::string& kind = row[5 + at];
    if ((kind != "object" && kind != "sky") || std::stoi(row[7 + at]) == 0) continue;
    const OffsetDateTime t = parse_offset_date_time(row[1] + "T" + row[2] + row[3], "csv");
    if (!first || seconds_between(*first, t) < 0) first = t;
    const std::string group = group_column && !row[*group_column].empty() ? " (" + row[*group_column] + ")" : "";
    expected[row[6 + at] + group].emplace_back(seconds_between({}, t), std::stod(row[8 + at]));
  }
  const SvgPlot plot = read_svg_plot(read_file(svg));
  ASSERT_TRUE(first) << "no object or sky rows in the CSV";
  ASSERT_GT(plot.x_per_pixel, 0.0);
  ASSERT_GT(plot.y_per_pixel, 0.0);
  ASSERT_EQ(plot.series.size(), expected.size());
  for (const SvgPlotSeries& series : plot.series) {
    SCOPED_TRACE(series.label);
    std::vector<std::pair<double, double>> want = expected[series.label];
    std::sort(want.begin(), want.end());  // the plot draws each line in time order
    ASSERT_EQ(series.points.size(), want.size());
    for (std::size_t k = 0; k < want.size(); ++k) {
      const double hours = (want[k].first - seconds_between({}, *first)) / 3600.0;
      EXPECT_NEAR(series.points[k].first, hours, 2 * plot.x_per_pixel);
      EXPECT_NEAR(series.points[k].second, want[k].second, 2 * plot.y_per_pixel);
    }
  }
}

}  // namespace skylit::testing
