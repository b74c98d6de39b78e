// Nice ticks, axis ranges and the pixel layout of a plot (plot_layout.h).
#include "skylit/figures/plot_layout.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace skylit {

double nice_step(double lo, double hi, int target) {
  const double span = hi - lo;
  if (!std::isfinite(span) || !(span > 0) || target < 1) return 0;
  const double raw = span / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * magnitude >= raw * (1 - 1e-9)) return m * magnitude;
  return 10 * magnitude;
}

namespace {

// Multiples of `step` in [lo, hi], computed as k·step (not by accumulation, which drifts)
// and snapped to 0 when rounding leaves a tiny remainder.
std::vector<double> multiples_within(double lo, double hi, double step) {
  std::vector<double> ticks;
  if (!(step > 0)) return ticks;
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  if (!(last - first < 1000)) return ticks;  // cannot happen with nice_step; a guard
  for (double k = first; k <= last; ++k) ticks.push_back(k == 0 ? 0.0 : k * step);
  return ticks;
}

std::string chars(double v, std::chars_format format, int precision) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, format, precision);
  return std::string(buffer, result.ptr);
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  return multiples_within(lo, hi, nice_step(lo, hi, target));
}

std::string tick_label(double value, double step) {
  if (!std::isfinite(value)) return "";
  if (step > 0 && std::abs(value) < step * 1e-6) value = 0;  // rounding of k·step
  if (value == 0) value = 0.0;                               // and never "-0"
  const int step_exponent = step > 0 ? int(std::floor(std::log10(step) + 1e-9)) : 0;
  const double magnitude = std::abs(value);
  // to_chars is locale-independent: a German locale must not turn 0.5 into "0,5".
  if (magnitude >= 1e6 || (magnitude > 0 && magnitude < 1e-4)) {
    const int value_exponent = int(std::floor(std::log10(magnitude) + 1e-9));
    return chars(value, std::chars_format::scientific, std::max(1, value_exponent - step_exponent));
  }
  return chars(value, std::chars_format::fixed, std::max(0, -step_exponent));
}

AxisScale axis_for_data(double lo, double hi, bool pad_to_ticks, bool include_zero) {
  AxisScale axis;
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    lo = 0;
    hi = 1;
  }
  if (include_zero) {
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
  }
  if (!(hi > lo)) {  // a single value: a range around it, so that no mapping divides by 0
    const double pad = lo == 0 ? 1.0 : 0.5 * std::abs(lo);
    if (lo != 0) lo -= pad;
    hi += pad;
  }
  // (A span beyond the largest double gets no ticks, and its points all map to one side.)
  if (pad_to_ticks && std::isfinite(hi - lo)) {
    // A little headroom first, so that an extreme which happens to lie on a tick is not
    // drawn on the frame; it never crosses zero, so an axis from 0 stays one.
    const double headroom = 0.02 * (hi - lo);
    lo = lo >= 0 ? std::max(0.0, lo - headroom) : lo - headroom;
    hi = hi <= 0 ? std::min(0.0, hi + headroom) : hi + headroom;
  }
  axis.step = nice_step(lo, hi);
  if (pad_to_ticks && axis.step > 0) {
    const double padded_lo = std::floor(lo / axis.step + 1e-9) * axis.step;
    const double padded_hi = std::ceil(hi / axis.step - 1e-9) * axis.step;
    if (std::isfinite(padded_lo) && std::isfinite(padded_hi) && padded_hi > padded_lo) {
      lo = padded_lo;
      hi = padded_hi;
    }
  }
  axis.lo = lo;
  axis.hi = hi;
  axis.ticks = multiples_within(lo, hi, axis.step);
  return axis;
}

Rgb8 series_colour(std::size_t index) {
  static constexpr Rgb8 kPalette[] = {{0, 114, 178}, {213, 94, 0},   {0, 158, 115}, {204, 121, 167},
                                      {230, 159, 0}, {86, 180, 233}, {0, 0, 0},     {240, 228, 66}};
  return kPalette[index % std::size(kPalette)];
}

namespace {

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return lo > hi; }
};

int widest_label(const AxisScale& axis) {
  int w = 0;
  for (double t : axis.ticks) w = std::max(w, text_width(tick_label(t, axis.step)));
  return w;
}

}  // namespace

PlotLayout plot_layout(const Plot& plot, int width, int height) {
  Range x, y, y2;
  bool uses_y2 = false;
  for (const PlotSeries& s : plot.series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("plot series \"" + s.label + "\": " + std::to_string(s.x.size()) + " x values but " +
                                  std::to_string(s.y.size()) + " y values");
    uses_y2 = uses_y2 || s.right_axis;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x.add(s.x[i]);
      (s.right_axis ? y2 : y).add(s.y[i]);
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PlotLayout layout;
  layout.width = width;
  layout.height = height;
  layout.has_y2 = uses_y2;
  layout.x = axis_for_data(x.empty() ? nan : x.lo, x.empty() ? nan : x.hi, false, false);
  layout.y = axis_for_data(y.empty() ? nan : y.lo, y.empty() ? nan : y.hi, true, plot.y_include_zero);
  layout.y2 = axis_for_data(y2.empty() ? nan : y2.lo, y2.empty() ? nan : y2.hi, true, plot.y_include_zero);

  const int margin = 14, gap = 4, th = text_height(1);
  layout.title_y = margin;
  layout.top = plot.title.empty() ? margin + th / 2 : margin + text_height(kPlotTitleScale) + 12;
  layout.y_label_x = margin;
  layout.left = margin + (plot.y_label.empty() ? 0 : th + 2 * gap) + widest_label(layout.y) + gap + kTickLength;
  if (layout.has_y2) {
    layout.right =
        width - 1 - margin - (plot.y2_label.empty() ? 0 : th + 2 * gap) - widest_label(layout.y2) - gap - kTickLength;
    layout.y2_tick_label_x = layout.right + kTickLength + gap + 1;
    layout.y2_label_x = width - margin - th;
  } else {
    const int last_x_label = layout.x.ticks.empty() ? 0 : text_width(tick_label(layout.x.ticks.back(), layout.x.step));
    layout.right = width - 1 - margin - std::max(last_x_label / 2, 2 * gap);
  }

  // The legend flows left to right under the x axis label, wrapping at the frame's width.
  const int row_height = th + gap;
  int at_x = layout.left, row = 0;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    std::string text = s.label.empty() ? "series " + std::to_string(i + 1) : s.label;
    if (s.right_axis) text += " (right axis)";
    const int entry = kLegendSwatch + 2 * gap + text_width(text);
    if (at_x > layout.left && at_x + entry > layout.right) {
      at_x = layout.left;
      ++row;
    }
    layout.legend.push_back({at_x, row, std::move(text), series_colour(i)});
    at_x += entry + 5 * gap;
  }
  const int legend_height = layout.legend.empty() ? 0 : (row + 1) * row_height + 2 * gap;
  const int legend_top = height - margin - legend_height + 2 * gap;
  for (LegendItem& item : layout.legend) item.y = legend_top + item.y * row_height;

  layout.x_label_y = height - margin - legend_height - (plot.x_label.empty() ? 0 : th);
  layout.x_tick_label_y = layout.x_label_y - (plot.x_label.empty() ? 0 : gap) - th;
  layout.bottom = layout.x_tick_label_y - gap - kTickLength - 1;
  // Absurdly long labels or legends squeeze the frame, but never turn it inside out.
  layout.right = std::max(layout.right, layout.left + 1);
  layout.bottom = std::max(layout.bottom, layout.top + 1);
  return layout;
}

}  // namespace skylit
