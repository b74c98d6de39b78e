// A sun study's statistics over time (study_statistics.h).
#include "skylit/figures/study_statistics.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "skylit/sun/time_steps.h"

namespace skylit {

namespace {

void check_sizes(const std::vector<AnimationFrame>& frames, const std::vector<RenderStatistics>& statistics,
                 const std::vector<std::string>& groups) {
  if (frames.size() != statistics.size() || frames.empty() || (!groups.empty() && groups.size() != frames.size()))
    throw std::invalid_argument("study statistics: one set of statistics (and group) per frame, and one frame");
}

}  // namespace

std::string study_statistics_csv(const std::vector<AnimationFrame>& frames,
                                 const std::vector<RenderStatistics>& statistics,
                                 const std::vector<std::string>& groups) {
  check_sizes(frames, statistics, groups);
  std::string out;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const AnimationFrame& f = frames[i];
    char altitude[32];
    std::snprintf(altitude, sizeof altitude, "%.3f", f.sun_altitude_deg);
    const std::string lead = std::to_string(f.number) + "," + format_date(f.time) + "," + format_clock(f.time) + "," +
                             format_offset(f.time.utc_offset_minutes) + "," + altitude + "," +
                             (groups.empty() ? "" : csv_field(groups[i]) + ",");
    const std::string rows = statistics_csv(statistics[i]);
    std::size_t start = rows.find('\n') + 1;  // past the header
    if (i == 0)
      out += std::string("frame,date,time,utc_offset,sun_altitude_deg,") + (groups.empty() ? "" : "group,") +
             rows.substr(0, start);
    while (start < rows.size()) {
      const std::size_t end = rows.find('\n', start);
      out += lead + rows.substr(start, end + 1 - start);
      start = end + 1;
    }
  }
  return out;
}

Plot study_statistics_plot(const std::string& title, const std::vector<AnimationFrame>& frames,
                           const std::vector<RenderStatistics>& statistics, const std::vector<std::string>& groups) {
  check_sizes(frames, statistics, groups);
  std::size_t first = 0, last = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (seconds_between(frames[first].time, frames[i].time) < 0) first = i;
    if (seconds_between(frames[last].time, frames[i].time) > 0) last = i;
  }
  const double span_h = seconds_between(frames[first].time, frames[last].time) / 3600.0;
  const bool in_days = span_h > 72;
  Plot plot;
  plot.title = title;
  plot.x_label = std::string(in_days ? "days" : "hours") + " from " + format_offset_date_time(frames[first].time);
  plot.y_label = "mean luminance (cd/m²)";
  // Series in the order objects first appear, then the sky; a frame where an object is
  // out of sight leaves a gap (NaN) in its line.
  std::vector<PlotSeries> series;
  std::map<std::string, std::size_t> index_of;
  std::vector<std::string> group_of;  // each series' group
  const auto group = [&](std::size_t frame) { return groups.empty() ? std::string() : groups[frame]; };
  const auto point = [&](const std::string& object, std::size_t frame, double mean) {
    const std::string name = group(frame).empty() ? object : object + " (" + group(frame) + ")";
    auto [it, added] = index_of.try_emplace(name, series.size());
    if (added) {
      group_of.push_back(group(frame));
      PlotSeries s;
      s.label = name;
      s.x.assign(frames.size(), 0.0);
      s.y.assign(frames.size(), std::numeric_limits<double>::quiet_NaN());
      series.push_back(std::move(s));
    }
    series[it->second].y[frame] = mean;
  };
  for (std::size_t i = 0; i < frames.size(); ++i) {
    for (const NamedSummary& o : statistics[i].objects)
      if (o.luminance.pixels > 0) point(o.name, i, o.luminance.mean);
    if (statistics[i].sky.pixels > 0) point("sky", i, statistics[i].sky.mean);
  }
  // Time order, and only a group's own frames in its lines.
  std::vector<std::size_t> order(frames.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return seconds_between(frames[a].time, frames[b].time) > 0; });
  for (std::size_t k = 0; k < series.size(); ++k) {
    PlotSeries& s = series[k];
    PlotSeries ordered;
    ordered.label = s.label;
    for (const std::size_t i : order) {
      if (group(i) != group_of[k]) continue;
      const double hours = seconds_between(frames[first].time, frames[i].time) / 3600.0;
      ordered.x.push_back(in_days ? hours / 24.0 : hours);
      ordered.y.push_back(s.y[i]);
    }
    s = std::move(ordered);
  }
  plot.series = std::move(series);
  return plot;
}

}  // namespace skylit
