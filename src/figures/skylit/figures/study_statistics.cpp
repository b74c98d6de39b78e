// A sun study's statistics over time (study_statistics.h).
#include "skylit/figures/study_statistics.h"

#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "skylit/sun/time_steps.h"

namespace skylit {

namespace {

void check_sizes(const std::vector<AnimationFrame>& frames, const std::vector<RenderStatistics>& statistics) {
  if (frames.size() != statistics.size() || frames.empty())
    throw std::invalid_argument("study statistics: one set of statistics per frame, and at least one frame");
}

}  // namespace

std::string study_statistics_csv(const std::vector<AnimationFrame>& frames,
                                 const std::vector<RenderStatistics>& statistics) {
  check_sizes(frames, statistics);
  std::string out;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const AnimationFrame& f = frames[i];
    char altitude[32];
    std::snprintf(altitude, sizeof altitude, "%.3f", f.sun_altitude_deg);
    const std::string lead = std::to_string(f.number) + "," + format_date(f.time) + "," + format_clock(f.time) + "," +
                             format_offset(f.time.utc_offset_minutes) + "," + altitude + ",";
    const std::string rows = statistics_csv(statistics[i]);
    std::size_t start = rows.find('\n') + 1;  // past the header
    if (i == 0) out += "frame,date,time,utc_offset,sun_altitude_deg," + rows.substr(0, start);
    while (start < rows.size()) {
      const std::size_t end = rows.find('\n', start);
      out += lead + rows.substr(start, end + 1 - start);
      start = end + 1;
    }
  }
  return out;
}

Plot study_statistics_plot(const std::string& title, const std::vector<AnimationFrame>& frames,
                           const std::vector<RenderStatistics>& statistics) {
  check_sizes(frames, statistics);
  const double span_h = seconds_between(frames.front().time, frames.back().time) / 3600.0;
  const bool in_days = span_h > 72;
  Plot plot;
  plot.title = title;
  plot.x_label = std::string(in_days ? "days" : "hours") + " from " + format_offset_date_time(frames.front().time);
  plot.y_label = "mean luminance (cd/m²)";
  // Series in the order objects first appear, then the sky; a frame where an object is
  // out of sight leaves a gap (NaN) in its line.
  std::vector<PlotSeries> series;
  std::map<std::string, std::size_t> index_of;
  const auto point = [&](const std::string& name, std::size_t frame, double mean) {
    auto [it, added] = index_of.try_emplace(name, series.size());
    if (added) {
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
  for (PlotSeries& s : series)
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const double hours = seconds_between(frames.front().time, frames[i].time) / 3600.0;
      s.x[i] = in_days ? hours / 24.0 : hours;
    }
  plot.series = std::move(series);
  return plot;
}

}  // namespace skylit
