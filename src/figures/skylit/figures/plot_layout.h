// What the PNG and SVG plot renderers share (plot.h): axis ranges with ticks at "nice"
// numbers (1, 2 or 5 × 10^k apart), tick label text, series colours, and where every
// part of the figure goes, in pixels. Measuring text with the bitmap font for both
// keeps the two renderings alike; SVG text is sized to match it roughly.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "skylit/figures/plot.h"
#include "skylit/figures/raster.h"

namespace skylit {

// The step between ticks for the range [lo, hi]: the smallest of 1, 2, 5 × 10^k that
// gives at most about `target` intervals. 0 for an empty, reversed or non-finite range.
double nice_step(double lo, double hi, int target = 5);

// Multiples of nice_step(lo, hi, target) within [lo, hi] (ends included within rounding),
// e.g. 0–1.83 → 0, 0.5, 1, 1.5 and 380–780 → 400, 500, 600, 700.
std::vector<double> nice_ticks(double lo, double hi, int target = 5);

// A tick's text: as many decimals as the step needs ("0.5", "1.0", "400"), or scientific
// notation for very large or small magnitudes ("2.0e-05"); never "-0".
std::string tick_label(double value, double step);

struct AxisScale {
  double lo = 0, hi = 1;      // the axis' range, lo < hi
  double step = 0.2;          // between ticks
  std::vector<double> ticks;  // within [lo, hi]
  // Position of v between the pixel coordinates p_lo (at lo) and p_hi (at hi).
  double map(double v, double p_lo, double p_hi) const { return p_lo + (v - lo) / (hi - lo) * (p_hi - p_lo); }
};

// The axis for data spanning [lo, hi] (NaN for no data: the range 0–1). `pad_to_ticks`
// (y axes) adds 2 % headroom, not across zero, and widens the range to the enclosing
// ticks; `include_zero` reaches to 0 when the data are of one sign. A single value v gets a range around it, so that no
// mapping divides by zero.
AxisScale axis_for_data(double lo, double hi, bool pad_to_ticks, bool include_zero);

// Distinct colours, by series index (cycling): the Okabe–Ito palette (Okabe & Ito 2008,
// "Color Universal Design"), which stays distinct for the common colour-vision
// deficiencies, its yellow last because it is faint on white.
Rgb8 series_colour(std::size_t index);

struct LegendItem {
  int x = 0, y = 0;  // top-left of the entry: swatch, then text
  std::string text;
  Rgb8 colour;
};

struct PlotLayout {
  int width = kPlotWidth, height = kPlotHeight;
  // The frame of the plot area: lines along pixel columns left and right, rows top and
  // bottom. Data map to pixel centres, so an axis' lo lies at left + 0.5 (x) or
  // bottom + 0.5 (y).
  int left = 0, top = 0, right = 0, bottom = 0;
  AxisScale x, y, y2;
  bool has_y2 = false;
  int title_y = 0;          // top of the title text (scale kPlotTitleScale)
  int x_tick_label_y = 0;   // top of the x tick labels
  int x_label_y = 0;        // top of the x axis label
  int y_label_x = 0;        // left of the (turned) y axis label
  int y2_tick_label_x = 0;  // left of the right axis' tick labels
  int y2_label_x = 0;       // left of the (turned) right axis label
  std::vector<LegendItem> legend;

  double px(double x_value) const { return x.map(x_value, left + 0.5, right + 0.5); }
  double py(double y_value, bool right_axis) const {
    return (right_axis ? y2 : y).map(y_value, bottom + 0.5, top + 0.5);
  }
};

inline constexpr int kPlotTitleScale = 2;
inline constexpr int kTickLength = 5;
inline constexpr int kLegendSwatch = 22;  // length of the line shown before a legend label
inline constexpr double kSeriesLineWidth = 2.0;

// std::invalid_argument if a series' x and y differ in length.
PlotLayout plot_layout(const Plot& plot, int width = kPlotWidth, int height = kPlotHeight);

}  // namespace skylit
