// The raster rendering of a plot (plot.h) on the layout of plot_layout.h: grid, series
// as anti-aliased lines, then the frame, ticks and text on top so that data never hide
// them.
#include <cmath>
#include <string>
#include <vector>

#include "skylit/figures/plot.h"
#include "skylit/figures/plot_layout.h"

namespace skylit {
namespace {

constexpr Rgb8 kGrid{225, 225, 225};

int column_of(double px) { return static_cast<int>(std::floor(px)); }

void draw_series(Raster& raster, const PlotLayout& layout, const PlotSeries& s, Rgb8 colour) {
  std::vector<PointF> points;
  points.reserve(s.x.size());
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const bool finite = std::isfinite(s.x[i]) && std::isfinite(s.y[i]);
    const double nan = std::nan("");
    // A NaN point breaks the line there (draw_polyline skips it and starts anew).
    points.push_back(finite ? PointF{layout.px(s.x[i]), layout.py(s.y[i], s.right_axis)} : PointF{nan, nan});
  }
  draw_polyline(raster, points, colour, kSeriesLineWidth);
  // A point without finite neighbours is no line at all: mark it with a bigger dot.
  const auto finite = [&](std::size_t i) { return i < points.size() && std::isfinite(points[i].x); };
  for (std::size_t i = 0; i < points.size(); ++i)
    if (finite(i) && !finite(i - 1) && !finite(i + 1))  // i − 1 wraps to a huge index at 0
      draw_line(raster, points[i], points[i], colour, 2 * kSeriesLineWidth);
}

void draw_y_axis(Raster& raster, const PlotLayout& layout, const AxisScale& axis, bool right_side) {
  for (double t : axis.ticks) {
    const int row = column_of(axis.map(t, layout.bottom + 0.5, layout.top + 0.5));
    const std::string label = tick_label(t, axis.step);
    const int label_top = row - text_height() / 2;
    if (right_side) {
      fill_rect(raster, layout.right + 1, row, kTickLength, 1, kBlack);
      draw_text(raster, layout.y2_tick_label_x, label_top, label, kBlack);
    } else {
      fill_rect(raster, layout.left - kTickLength, row, kTickLength, 1, kBlack);
      draw_text(raster, layout.left - kTickLength - 4 - text_width(label), label_top, label, kBlack);
    }
  }
}

}  // namespace

Raster render_plot_png(const Plot& plot) {
  const PlotLayout layout = plot_layout(plot);
  Raster raster(layout.width, layout.height, kWhite);
  const int frame_w = layout.right - layout.left + 1, frame_h = layout.bottom - layout.top + 1;

  for (double t : layout.x.ticks) fill_rect(raster, column_of(layout.px(t)), layout.top, 1, frame_h, kGrid);
  for (double t : layout.y.ticks) fill_rect(raster, layout.left, column_of(layout.py(t, false)), frame_w, 1, kGrid);

  for (std::size_t i = 0; i < plot.series.size(); ++i) draw_series(raster, layout, plot.series[i], series_colour(i));
  // Wipe what a thick line drew outside the frame (only ever its rounded end).
  fill_rect(raster, 0, 0, layout.width, layout.top, kWhite);
  fill_rect(raster, 0, layout.bottom + 1, layout.width, layout.height, kWhite);
  fill_rect(raster, 0, 0, layout.left, layout.height, kWhite);
  fill_rect(raster, layout.right + 1, 0, layout.width, layout.height, kWhite);

  // Frame.
  fill_rect(raster, layout.left, layout.top, frame_w, 1, kBlack);
  fill_rect(raster, layout.left, layout.bottom, frame_w, 1, kBlack);
  fill_rect(raster, layout.left, layout.top, 1, frame_h, kBlack);
  fill_rect(raster, layout.right, layout.top, 1, frame_h, kBlack);

  for (double t : layout.x.ticks) {
    const int column = column_of(layout.px(t));
    fill_rect(raster, column, layout.bottom + 1, 1, kTickLength, kBlack);
    const std::string label = tick_label(t, layout.x.step);
    draw_text(raster, column - text_width(label) / 2, layout.x_tick_label_y, label, kBlack);
  }
  draw_y_axis(raster, layout, layout.y, false);
  if (layout.has_y2) draw_y_axis(raster, layout, layout.y2, true);

  const int middle_x = (layout.left + layout.right + 1) / 2, middle_y = (layout.top + layout.bottom + 1) / 2;
  draw_text(raster, middle_x - text_width(plot.title, kPlotTitleScale) / 2, layout.title_y, plot.title, kBlack,
            kPlotTitleScale);
  draw_text(raster, middle_x - text_width(plot.x_label) / 2, layout.x_label_y, plot.x_label, kBlack);
  draw_text(raster, layout.y_label_x, middle_y + text_width(plot.y_label) / 2, plot.y_label, kBlack, 1,
            TextDirection::up);
  if (layout.has_y2)
    draw_text(raster, layout.y2_label_x, middle_y + text_width(plot.y2_label) / 2, plot.y2_label, kBlack, 1,
              TextDirection::up);

  for (const LegendItem& item : layout.legend) {
    // The centre of the text's middle pixel row (integer division on purpose).
    const int middle_row = item.y + text_height() / 2;
    const double swatch_y = middle_row + 0.5;
    draw_line(raster, {item.x + 0.5, swatch_y}, {item.x + kLegendSwatch - 0.5, swatch_y}, item.colour,
              kSeriesLineWidth);
    draw_text(raster, item.x + kLegendSwatch + 8, item.y, item.text, kBlack);
  }
  return raster;
}

}  // namespace skylit
