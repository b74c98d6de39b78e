// Plots (plot.h, plot_layout.h): ticks at nice numbers and their labels, axes that
// never divide by zero, the right axis only when used, a PNG that decodes to the
// documented size with each series drawn in its colour where its data lie, an SVG with
// escaped labels and one polyline per run of points, and the file contract (extension,
// InputError naming the path, nothing left behind).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../io/image_test_util.h"
#include "../io/png_read_util.h"
#include "skylit/core/error.h"
#include "skylit/figures/plot.h"
#include "skylit/figures/plot_layout.h"

namespace skylit {
namespace {

void expect_ticks(double lo, double hi, const std::vector<double>& expected) {
  const std::vector<double> ticks = nice_ticks(lo, hi);
  ASSERT_EQ(ticks.size(), expected.size()) << lo << "–" << hi;
  for (std::size_t i = 0; i < ticks.size(); ++i)
    EXPECT_NEAR(ticks[i], expected[i], 1e-12 * (1 + std::abs(expected[i])));
}

TEST(PlotTicks, AreNiceNumbersWithinTheRange) {
  expect_ticks(0, 1.83, {0, 0.5, 1, 1.5});
  expect_ticks(380, 780, {400, 500, 600, 700});
  expect_ticks(0, 0.1, {0, 0.02, 0.04, 0.06, 0.08, 0.1});
  expect_ticks(-3, 7, {-2, 0, 2, 4, 6});
  expect_ticks(0, 2.3e-5, {0, 5e-6, 1e-5, 1.5e-5, 2e-5});
  expect_ticks(1e6, 3.5e6, {1e6, 1.5e6, 2e6, 2.5e6, 3e6, 3.5e6});
  EXPECT_DOUBLE_EQ(nice_step(0, 1.83), 0.5);
  EXPECT_DOUBLE_EQ(nice_step(380, 780), 100);
  // Nothing to divide: no ticks rather than a division by zero or an endless loop.
  EXPECT_TRUE(nice_ticks(5, 5).empty());
  EXPECT_TRUE(nice_ticks(7, 3).empty());
  EXPECT_TRUE(nice_ticks(0, std::numeric_limits<double>::infinity()).empty());
  EXPECT_TRUE(nice_ticks(std::nan(""), 1).empty());
}

TEST(PlotTicks, LabelsShowTheDecimalsTheStepNeeds) {
  EXPECT_EQ(tick_label(0.5, 0.5), "0.5");
  EXPECT_EQ(tick_label(1, 0.5), "1.0");
  EXPECT_EQ(tick_label(400, 100), "400");
  EXPECT_EQ(tick_label(0.06, 0.02), "0.06");
  EXPECT_EQ(tick_label(-2, 2), "-2");
  EXPECT_EQ(tick_label(-1e-17, 0.5), "0.0");  // k·step rounding, and never "-0"
  EXPECT_EQ(tick_label(1.5e-5, 5e-6), "1.5e-05");
  EXPECT_EQ(tick_label(3e6, 1e6), "3.0e+06");
}

TEST(PlotTicks, AxesNeverDegenerate) {
  const double nan = std::nan("");
  for (auto [lo, hi] : std::vector<std::pair<double, double>>{{5, 5}, {0, 0}, {-2, -2}, {nan, nan}, {1e-300, 1e-300}})
    for (bool pad : {false, true})
      for (bool zero : {false, true}) {
        const AxisScale a = axis_for_data(lo, hi, pad, zero);
        EXPECT_TRUE(std::isfinite(a.lo) && std::isfinite(a.hi)) << lo;
        EXPECT_LT(a.lo, a.hi) << lo;
        if (std::isfinite(lo)) {  // braces: EXPECT_* expands to an if/else
          EXPECT_TRUE(a.lo <= lo && lo <= a.hi) << lo;
        }
      }
  // A y axis over 0–1.83 is widened to its ticks: 0–2 by 0.5.
  const AxisScale y = axis_for_data(0.02, 1.83, true, true);
  EXPECT_EQ(y.lo, 0);
  EXPECT_DOUBLE_EQ(y.hi, 2);
  EXPECT_EQ(y.ticks.size(), 5u);
  // An x axis keeps the data's range.
  const AxisScale x = axis_for_data(380, 780, false, false);
  EXPECT_EQ(x.lo, 380);
  EXPECT_EQ(x.hi, 780);
}

// Three spectra like the first use: two irradiances on the left axis, a radiance ten
// times smaller on the right.
Plot spectra_plot() {
  Plot p;
  p.title = "Clear sky at noon";
  p.x_label = "wavelength λ (nm)";
  p.y_label = "irradiance (W·m⁻²·nm⁻¹)";
  p.y2_label = "radiance (W·m⁻²·sr⁻¹·nm⁻¹)";
  PlotSeries direct{"direct normal", {}, {}}, diffuse{"diffuse horizontal", {}, {}},
      zenith{"zenith radiance", {}, {}, true};
  for (int l = 380; l <= 780; l += 10) {
    direct.x.push_back(l), direct.y.push_back(1.8 - 0.5 * std::abs(l - 560) / 220.0);
    diffuse.x.push_back(l), diffuse.y.push_back(0.45 * std::exp(-(l - 380) / 200.0));
    zenith.x.push_back(l), zenith.y.push_back(0.09 * std::exp(-(l - 380) / 120.0));
  }
  p.series = {direct, diffuse, zenith};
  return p;
}

TEST(PlotLayout, RightAxisOnlyWhenASeriesUsesIt) {
  Plot p = spectra_plot();
  PlotLayout layout = plot_layout(p);
  ASSERT_TRUE(layout.has_y2);
  EXPECT_EQ(layout.y2.lo, 0);
  EXPECT_GE(layout.y2.hi, 0.09);
  EXPECT_LE(layout.y2.hi, 0.1 + 1e-12);  // its own scale, not the left axis' 0–2
  EXPECT_GE(layout.y.hi, 1.8);
  p.series.pop_back();
  layout = plot_layout(p);
  EXPECT_FALSE(layout.has_y2);
  EXPECT_EQ(layout.legend.size(), 2u);
}

TEST(PlotPng, HasTheDocumentedSizeAndEachSeriesInItsColour) {
  test::ScratchFolder dir("plot-png");
  const Plot plot = spectra_plot();
  write_plot(plot, dir / "spectra.png");
  const Raster png = test::read_png_raster(dir / "spectra.png");
  ASSERT_EQ(png.width, kPlotWidth);
  ASSERT_EQ(png.height, kPlotHeight);
  const PlotLayout layout = plot_layout(plot);
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    const Rgb8 colour = series_colour(s);
    // Where the series' data lie, the pixel is the series' colour (the 2-px line covers
    // the pixel holding each point fully) ...
    const PlotSeries& series = plot.series[s];
    const std::size_t i = 30;  // 680 nm, where the three curves are apart
    const double x = layout.px(series.x[i]), y = layout.py(series.y[i], series.right_axis);
    EXPECT_EQ(png.at(int(x), int(y)), colour) << series.label;
    // ... and the colour covers far more pixels than the legend's swatch alone.
    int count = 0;
    for (int py = layout.top; py <= layout.bottom; ++py)
      for (int px = layout.left; px <= layout.right; ++px) count += png.at(px, py) == colour;
    EXPECT_GT(count, 400) << series.label;
  }
  // The frame is drawn, and the series are distinct colours.
  EXPECT_EQ(png.at(layout.left, (layout.top + layout.bottom) / 2), kBlack);
  EXPECT_NE(series_colour(0), series_colour(1));
  EXPECT_NE(series_colour(1), series_colour(2));
  EXPECT_NE(series_colour(0), series_colour(2));
}

TEST(PlotPng, AwkwardDataDrawWithoutFailing) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  Plot p;
  p.title = "awkward";
  p.series = {{"empty", {}, {}},
              {"constant", {1, 2, 3}, {2.5, 2.5, 2.5}},
              {"holes", {0, 1, nan, 3, 4}, {1, inf, 2, 3, -inf}},
              {"one point", {2}, {5}, true}};
  Raster r;
  ASSERT_NO_THROW(r = render_plot_png(p));
  EXPECT_EQ(r.width, kPlotWidth);
  EXPECT_EQ(r.height, kPlotHeight);
  const PlotLayout layout = plot_layout(p);
  EXPECT_LT(layout.y.lo, layout.y.hi);
  EXPECT_LT(layout.y2.lo, layout.y2.hi);
  // The constant series lies inside the frame, drawn in its colour.
  EXPECT_EQ(r.at(int(layout.px(2)), int(layout.py(2.5, false))), series_colour(1));
  // A lone point is marked with a dot; it lies inside the frame, not on it (headroom).
  EXPECT_EQ(r.at(int(layout.px(2)), int(layout.py(5, true))), series_colour(3));
  EXPECT_GT(layout.py(5, true), layout.top + 2 * kSeriesLineWidth);
  // Labels and legends far too long for the figure squeeze the frame but do not break it.
  Plot crowded;
  crowded.y_label = std::string(300, 'y');
  for (int i = 0; i < 60; ++i)
    crowded.series.push_back({std::string(40, 'a' + i % 26), {0, 1e-300 * i}, {-1e300, 1e300}, i % 2 == 1});
  Raster c;
  ASSERT_NO_THROW(c = render_plot_png(crowded));
  EXPECT_EQ(c.width, kPlotWidth);
  EXPECT_NO_THROW(render_plot_svg(crowded));
  // A span beyond the largest double: no ticks, but no NaN written either.
  const Plot huge{"", "", "", "", {{"huge", {-1e308, 1e308}, {-1e308, 1e308}}}};
  EXPECT_NO_THROW(render_plot_png(huge));
  EXPECT_EQ(render_plot_svg(huge).find("nan"), std::string::npos);
  // No data at all, and no series at all.
  EXPECT_NO_THROW(render_plot_png(Plot{"nothing", "", "", "", {{"nan", {nan}, {nan}}}}));
  EXPECT_NO_THROW(render_plot_png(Plot{}));
  EXPECT_NO_THROW(render_plot_svg(Plot{}));
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PlotSvg, HoldsEscapedLabelsAndAPolylinePerSeries) {
  Plot plot = spectra_plot();
  plot.title = "Sky <clear> & \"dry\"";
  plot.series[0].label = "a < b";
  const std::string svg = render_plot_svg(plot);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("Sky &lt;clear&gt; &amp; &quot;dry&quot;"), std::string::npos);
  EXPECT_NE(svg.find(">a &lt; b<"), std::string::npos);
  EXPECT_EQ(svg.find("a < b"), std::string::npos);
  EXPECT_EQ(svg.find("<clear>"), std::string::npos);
  // UTF-8 is kept as it is (the font of the viewer draws it, not ours).
  EXPECT_NE(svg.find("wavelength λ (nm)"), std::string::npos);
  EXPECT_NE(svg.find("radiance (W·m⁻²·sr⁻¹·nm⁻¹)"), std::string::npos);
  // One polyline per series, in its colour, with one point per datum.
  EXPECT_EQ(occurrences(svg, "<polyline"), 3u);
  for (std::size_t s = 0; s < 3; ++s) {
    const Rgb8 c = series_colour(s);
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c.r, c.g, c.b);
    const std::size_t group = svg.find(std::string("<g stroke=\"") + hex + "\">");
    ASSERT_NE(group, std::string::npos) << hex;
    const std::size_t begin = svg.find("points=\"", group) + 8, end = svg.find('"', begin);
    const std::string points = svg.substr(begin, end - begin);
    EXPECT_EQ(occurrences(points, ","), plot.series[s].x.size()) << hex;
  }
  // Ticks are labelled with nice numbers on all three axes.
  EXPECT_NE(svg.find(">600</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1.5</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.08</text>"), std::string::npos);
}

TEST(PlotSvg, BreaksLinesAtGapsAndStaysWellFormed) {
  Plot plot;
  plot.title = "bad \xFF bytes\x01 and \xC3";
  plot.series = {{"gappy", {1, 2, 3, std::nan(""), 5, 6}, {1, 2, 3, 4, 5, 6}}};
  const std::string svg = render_plot_svg(plot);
  EXPECT_EQ(occurrences(svg, "<polyline"), 2u);
  EXPECT_EQ(svg.find('\xFF'), std::string::npos);
  EXPECT_EQ(svg.find('\x01'), std::string::npos);
  EXPECT_NE(svg.find("bad \uFFFD bytes and \uFFFD"), std::string::npos);
}

TEST(PlotWrite, ExtensionChoosesTheFormat) {
  test::ScratchFolder dir("plot-write");
  const Plot plot = spectra_plot();
  write_plot(plot, dir / "a.SVG");
  write_plot(plot, dir / "b.png");
  EXPECT_EQ(test::listing(dir.path()), (std::vector<std::string>{"a.SVG", "b.png"}));
  const std::vector<uint8_t> svg = test::read_bytes(dir / "a.SVG");
  EXPECT_EQ(std::string(svg.begin(), svg.end()), render_plot_svg(plot));
  EXPECT_EQ(test::read_bytes(dir / "b.png").at(1), 'P');
}

TEST(PlotWrite, BadExtensionOrFolderIsInputErrorAndLeavesNothing) {
  test::ScratchFolder dir("plot-bad");
  const Plot plot = spectra_plot();
  for (const std::filesystem::path& path : {dir / "plot.pdf", dir / "plot", dir / "no-folder" / "plot.svg"}) {
    try {
      write_plot(plot, path);
      ADD_FAILURE() << "no InputError for " << path;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(test::listing(dir.path()).empty());
  // A caller's mismatched series is not a user error, and is found before any file.
  Plot bad = plot;
  bad.series[1].y.pop_back();
  EXPECT_THROW(write_plot(bad, dir / "plot.svg"), std::invalid_argument);
  EXPECT_TRUE(test::listing(dir.path()).empty());
}

}  // namespace
}  // namespace skylit
