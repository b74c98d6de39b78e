// The SVG rendering of a plot (plot.h) on the layout of plot_layout.h: text stays text
// (UTF-8 kept, XML-escaped), each series is one <polyline> per unbroken run of finite
// points, clipped to the plot area. Numbers are written with std::to_chars so the file
// does not depend on the locale.
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "skylit/figures/bitmap_font.h"
#include "skylit/figures/plot.h"
#include "skylit/figures/plot_layout.h"
#include "skylit/figures/utf8.h"

namespace skylit {
namespace {

// Pixel coordinate, 2 decimals at most ("12.5", "300").
std::string num(double v) {
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, std::round(v * 100) / 100 + 0.0, std::chars_format::fixed, 2);
  std::string s(buffer, result.ptr);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string hex(Rgb8 c) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s = "#";
  for (uint8_t v : {c.r, c.g, c.b}) {
    s += kDigits[v >> 4];
    s += kDigits[v & 15];
  }
  return s;
}

// SVG text whose box matches the bitmap font's at `scale`: `top` is the box's top, the
// baseline lies where the font's (under its 7 rows of capitals).
constexpr int kSvgFontSize = 11;

std::string text_element(double x, int top, std::string_view text, int scale, const char* anchor,
                         const std::string& extra = "") {
  if (text.empty()) return "";
  const int baseline = top + (kGlyphTopInCell + 7) * scale;
  return "<text x=\"" + num(x) + "\" y=\"" + num(baseline) + "\" text-anchor=\"" + anchor + "\"" +
         (scale == 1 ? "" : " font-size=\"" + std::to_string(kSvgFontSize * scale) + "\"") + extra + ">" +
         xml_text(text) + "</text>\n";
}

// A y-axis label turned to read upward, centred on (centre_x, centre_y).
std::string turned_text(int left, double centre_y, std::string_view text) {
  if (text.empty()) return "";
  const double x = left + (kGlyphTopInCell + 7);  // the baseline, now a vertical line
  return "<text transform=\"translate(" + num(x) + " " + num(centre_y) + ") rotate(-90)\" text-anchor=\"middle\">" +
         xml_text(text) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2) {
  return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) + "\"/>\n";
}

// One <polyline> per run of finite points; a lone point becomes a dot twice the line's width.
std::string series_element(const PlotLayout& layout, const PlotSeries& s, Rgb8 colour) {
  std::string out = "<g stroke=\"" + hex(colour) + "\">\n";
  std::string points;
  std::size_t count = 0;
  double last_x = 0, last_y = 0;
  const auto flush = [&] {
    if (count >= 2) out += "<polyline points=\"" + points + "\"/>\n";
    if (count == 1)
      out += "<circle cx=\"" + num(last_x) + "\" cy=\"" + num(last_y) + "\" r=\"" + num(kSeriesLineWidth) +
             "\" fill=\"" + hex(colour) + "\" stroke=\"none\"/>\n";
    points.clear();
    count = 0;
  };
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const double x = layout.px(s.x[i]), y = layout.py(s.y[i], s.right_axis);
    if (!std::isfinite(x) || !std::isfinite(y)) {  // a non-finite datum, or a span beyond double
      flush();
      continue;
    }
    last_x = x;
    last_y = y;
    if (count++ > 0) points += ' ';
    points += num(last_x) + "," + num(last_y);
  }
  flush();
  return out + "</g>\n";
}

std::string y_axis_elements(const PlotLayout& layout, const AxisScale& axis, bool right_side) {
  std::string ticks = "<g stroke=\"#000000\">\n", labels;
  for (double t : axis.ticks) {
    const double y = std::floor(axis.map(t, layout.bottom + 0.5, layout.top + 0.5)) + 0.5;
    const std::string label = tick_label(t, axis.step);
    const int top = int(std::floor(y)) - text_height() / 2;
    if (right_side) {
      ticks += line(layout.right + 1, y, layout.right + 1 + kTickLength, y);
      labels += text_element(layout.y2_tick_label_x, top, label, 1, "start");
    } else {
      ticks += line(layout.left - kTickLength, y, layout.left, y);
      labels += text_element(layout.left - kTickLength - 4, top, label, 1, "end");
    }
  }
  return ticks + "</g>\n" + labels;
}

}  // namespace

std::string render_plot_svg(const Plot& plot) {
  const PlotLayout layout = plot_layout(plot);
  const double l = layout.left + 0.5, r = layout.right + 0.5, t = layout.top + 0.5, b = layout.bottom + 0.5;
  std::string svg =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
      std::to_string(layout.width) + "\" height=\"" + std::to_string(layout.height) + "\" viewBox=\"0 0 " +
      std::to_string(layout.width) + " " + std::to_string(layout.height) +
      "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"" + std::to_string(kSvgFontSize) +
      "\">\n";
  if (!plot.title.empty()) svg += "<title>" + xml_text(plot.title) + "</title>\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  svg += "<defs><clipPath id=\"plot-area\"><rect x=\"" + num(l) + "\" y=\"" + num(t) + "\" width=\"" + num(r - l) +
         "\" height=\"" + num(b - t) + "\"/></clipPath></defs>\n";

  svg += "<g stroke=\"#e1e1e1\">\n";
  for (double v : layout.x.ticks) {
    const double x = std::floor(layout.px(v)) + 0.5;
    svg += line(x, t, x, b);
  }
  for (double v : layout.y.ticks) {
    const double y = std::floor(layout.py(v, false)) + 0.5;
    svg += line(l, y, r, y);
  }
  svg += "</g>\n";

  svg += "<g clip-path=\"url(#plot-area)\" fill=\"none\" stroke-width=\"" + num(kSeriesLineWidth) +
         "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  for (std::size_t i = 0; i < plot.series.size(); ++i) svg += series_element(layout, plot.series[i], series_colour(i));
  svg += "</g>\n";

  svg += "<rect x=\"" + num(l) + "\" y=\"" + num(t) + "\" width=\"" + num(r - l) + "\" height=\"" + num(b - t) +
         "\" fill=\"none\" stroke=\"#000000\"/>\n";
  std::string x_ticks = "<g stroke=\"#000000\">\n", x_labels;
  for (double v : layout.x.ticks) {
    const double x = std::floor(layout.px(v)) + 0.5;
    x_ticks += line(x, b, x, b + kTickLength);
    x_labels += text_element(x, layout.x_tick_label_y, tick_label(v, layout.x.step), 1, "middle");
  }
  svg += x_ticks + "</g>\n" + x_labels;
  svg += y_axis_elements(layout, layout.y, false);
  if (layout.has_y2) svg += y_axis_elements(layout, layout.y2, true);

  const double middle_x = (layout.left + layout.right + 1) / 2.0, middle_y = (layout.top + layout.bottom + 1) / 2.0;
  svg += text_element(middle_x, layout.title_y, plot.title, kPlotTitleScale, "middle");
  svg += text_element(middle_x, layout.x_label_y, plot.x_label, 1, "middle");
  svg += turned_text(layout.y_label_x, middle_y, plot.y_label);
  if (layout.has_y2) svg += turned_text(layout.y2_label_x, middle_y, plot.y2_label);

  for (const LegendItem& item : layout.legend) {
    // The centre of the text's middle pixel row (integer division on purpose).
    const int middle_row = item.y + text_height() / 2;
    const double y = middle_row + 0.5;
    svg += "<line x1=\"" + num(item.x) + "\" y1=\"" + num(y) + "\" x2=\"" + num(item.x + kLegendSwatch) + "\" y2=\"" +
           num(y) + "\" stroke=\"" + hex(item.colour) + "\" stroke-width=\"" + num(kSeriesLineWidth) + "\"/>\n";
    svg += text_element(item.x + kLegendSwatch + 8, item.y, item.text, 1, "start");
  }
  return svg + "</svg>\n";
}

}  // namespace skylit
