// Line plots of data series (spectra against wavelength, profiles, convergence) written
// as SVG (vector; text stays text, UTF-8 kept) or PNG (a raster drawn with the built-in
// bitmap font). Both share one layout (plot_layout.h): axes with ticks at "nice"
// numbers, axis labels, a legend naming each series in its own colour, and an optional
// second y axis on the right for series whose magnitudes differ from the rest.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "skylit/figures/raster.h"

namespace skylit {

struct PlotSeries {
  std::string label;
  // Same length. A point with a non-finite x or y is skipped and breaks the line there;
  // a point with no finite neighbour is marked with a dot.
  std::vector<double> x, y;
  bool right_axis = false;  // drawn against the right y axis (Plot::y2_label)
};

struct Plot {
  std::string title, x_label, y_label;
  std::string y2_label;  // the right axis, drawn only if a series uses it
  std::vector<PlotSeries> series;
  // Each y axis reaches down (or up) to 0 when its data are all of one sign, so that
  // magnitudes compare by eye; false fits the axis to the data alone.
  bool y_include_zero = true;
};

// By the extension (any case): .svg or .png (kPlotWidth × kPlotHeight pixels). Written
// through a temporary file renamed into place. InputError naming the path for another
// extension or a missing or unwritable folder, and then no file is left behind.
// std::invalid_argument if a series' x and y differ in length (a caller's bug).
void write_plot(const Plot& plot, const std::filesystem::path& path);

// The two renderings, for tests and for callers that embed a plot elsewhere.
Raster render_plot_png(const Plot& plot);
std::string render_plot_svg(const Plot& plot);

inline constexpr int kPlotWidth = 900;
inline constexpr int kPlotHeight = 560;

}  // namespace skylit
