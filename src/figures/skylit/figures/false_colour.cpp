// The false-colour image and its legend (false_colour.h).
#include "skylit/figures/false_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "skylit/core/file_names.h"
#include "skylit/figures/figure_file.h"
#include "skylit/figures/viridis.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image_encoders.h"

namespace skylit {
namespace {

constexpr int kMargin = 8;  // pixels at legend scale 1
// How much of the display image shows through the colours with settings.underlay:
// enough to recognise the scene, little enough that the colours still read.
constexpr double kUnderlayWeight = 0.35;
constexpr Rgb8 kInk{40, 40, 40};

double percentile_99(std::span<const float> values) {
  std::vector<float> finite;
  for (float v : values)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty()) return 0;
  const auto nth = finite.begin() + static_cast<std::ptrdiff_t>(0.99 * double(finite.size() - 1));
  std::nth_element(finite.begin(), nth, finite.end());
  return *nth;
}

// The smallest 1, 2 or 5 × 10^k at or above v > 0.
double nice_ceiling(double v) {
  const double decade = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= v * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

// Where value v lies on the scale, 0 … 1 (unclamped).
double scale_position(double v, const FalseColourLegend& legend) {
  if (!std::isfinite(v)) return 0;
  if (legend.scale == FalseColourScale::linear) return (v - legend.low) / (legend.high - legend.low);
  if (!(v > 0)) return 0;
  return std::log(v / legend.low) / std::log(legend.high / legend.low);
}

Rgb8 mix(Rgb8 a, Rgb8 b, double w) {
  auto m = [w](uint8_t x, uint8_t y) { return static_cast<uint8_t>(std::lround(x + w * (double(y) - double(x)))); };
  return {m(a.r, b.r), m(a.g, b.g), m(a.b, b.b)};
}

// Whether a legend step lies between values a and b (a contour runs between them).
bool step_between(double a, double b, const std::vector<double>& steps) {
  if (!std::isfinite(a) || !std::isfinite(b) || a == b) return false;
  const double lo = std::min(a, b), hi = std::max(a, b);
  return std::any_of(steps.begin(), steps.end(), [&](double s) { return lo < s && s <= hi; });
}

}  // namespace

FalseColourLegend false_colour_legend(std::span<const float> values, const FalseColourSettings& settings) {
  FalseColourLegend legend;
  const bool lux = settings.quantity == FalseColourQuantity::illuminance;
  legend.quantity = lux ? "illuminance" : "luminance";
  legend.unit = lux ? "lx" : "cd/m²";
  legend.scale = settings.scale;
  const double top = settings.max ? *settings.max : percentile_99(values);
  if (settings.scale == FalseColourScale::log) {
    legend.high = settings.max ? *settings.max : std::pow(10.0, std::ceil(std::log10(top > 0 ? top : 1.0)));
    legend.low = legend.high * std::pow(10.0, -settings.decades);
    legend.steps.push_back(legend.low);
    for (int k = static_cast<int>(std::floor(std::log10(legend.low))); k <= std::ceil(std::log10(legend.high)); ++k)
      for (double m : {1.0, 2.0, 5.0}) {
        const double v = m * std::pow(10.0, k);
        if (v > legend.low * (1 + 1e-9) && v < legend.high * (1 - 1e-9)) legend.steps.push_back(v);
      }
    legend.steps.push_back(legend.high);
  } else {
    legend.low = 0;
    legend.high = settings.max ? *settings.max : (top > 0 ? nice_ceiling(top) : 1.0);
    for (int i = 0; i <= 10; ++i) legend.steps.push_back(legend.high * i / 10.0);
  }
  return legend;
}

Rgb8 false_colour(double value, const FalseColourLegend& legend) {
  return viridis(std::clamp(scale_position(value, legend), 0.0, 1.0));
}

std::string false_colour_label(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

Raster render_false_colour(std::span<const float> values, int width, int height, const FalseColourSettings& settings,
                           std::span<const uint8_t> underlay_srgb, FalseColourLayout* layout) {
  if (width <= 0 || height <= 0 || values.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("render_false_colour: " + std::to_string(values.size()) + " values for " +
                                std::to_string(width) + "x" + std::to_string(height) + " pixels");
  if (settings.underlay && underlay_srgb.size() != 3 * values.size())
    throw std::invalid_argument("render_false_colour: the underlay does not match the image");
  const FalseColourLegend legend = false_colour_legend(values, settings);

  // The legend's size: three title lines, then one row per step.
  const int s = std::max(1, width / 512);
  const int row = text_height(s) + 2 * s, swatch = text_height(s);
  const std::string scale_name = settings.scale == FalseColourScale::log ? "log scale" : "linear scale";
  int text = std::max({text_width(legend.quantity, s), text_width(legend.unit, s), text_width(scale_name, s)});
  for (double v : legend.steps) text = std::max(text, swatch + 4 * s + text_width(false_colour_label(v), s));
  const int legend_width = text + 2 * kMargin * s;
  const int steps_top = kMargin * s + 3 * row + row / 2;
  const int legend_height = steps_top + int(legend.steps.size()) * row + kMargin * s;

  Raster raster(width + legend_width, std::max(height, legend_height), kWhite);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      Rgb8 colour = false_colour(values[i], legend);
      if (settings.underlay) {
        const uint8_t* p = &underlay_srgb[3 * i];
        colour = mix(colour, {p[0], p[1], p[2]}, kUnderlayWeight);
      }
      if (settings.contours && ((x + 1 < width && step_between(values[i], values[i + 1], legend.steps)) ||
                                (y + 1 < height && step_between(values[i], values[i + width], legend.steps))))
        colour = scale_position(values[i], legend) < 0.5 ? kWhite : kBlack;
      set_pixel(raster, x, y, colour);
    }

  const int x0 = width + kMargin * s;
  draw_text(raster, x0, kMargin * s, legend.quantity, kInk, s);
  draw_text(raster, x0, kMargin * s + row, legend.unit, kInk, s);
  draw_text(raster, x0, kMargin * s + 2 * row, scale_name, kInk, s);
  FalseColourLayout placed{x0, swatch, std::vector<int>(legend.steps.size())};
  for (std::size_t i = 0; i < legend.steps.size(); ++i) {
    const int y = steps_top + int(legend.steps.size() - 1 - i) * row;  // highest at the top
    fill_rect(raster, x0, y, swatch, swatch, false_colour(legend.steps[i], legend));
    draw_text(raster, x0 + swatch + 4 * s, y, false_colour_label(legend.steps[i]), kInk, s);
    placed.swatch_y[i] = y;
  }
  if (layout) *layout = placed;
  return raster;
}

std::vector<uint8_t> encode_false_colour(const XyzImage& image, std::span<const float> values,
                                         const FalseColourSettings& settings, const DisplayOptions& display) {
  std::vector<uint8_t> underlay;
  if (settings.underlay) underlay = display_srgb8(image, display);
  const Raster raster = render_false_colour(values, image.width, image.height, settings, underlay);
  return encode_png_rgb8(raster.width, raster.height, raster.rgb);
}

void write_false_colour(const XyzImage& image, std::span<const float> values, const std::filesystem::path& path,
                        const FalseColourSettings& settings, const DisplayOptions& display) {
  figure_extension(path, {".png"}, "a false-colour image");
  AtomicFile file(path);  // checks the folder before the work
  file.commit(encode_false_colour(image, values, settings, display));
}

bool is_false_colour_path(const std::filesystem::path& path) {
  const std::string name = lower_case(path.filename().string());
  for (const std::string suffix : {".falsecolor.png", ".falsecolour.png"})
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      return true;
  return false;
}

}  // namespace skylit
