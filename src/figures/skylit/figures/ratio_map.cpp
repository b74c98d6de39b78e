// render_ratio_map and write_ratio_map (ratio_map.h).
#include "skylit/figures/ratio_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "skylit/compare/region_comparison.h"
#include "skylit/figures/cool_warm.h"
#include "skylit/figures/figure_file.h"

namespace skylit {
namespace {

constexpr int kLegendBarWidth = 240;  // pixels at scale 1
constexpr int kMargin = 8;

bool finite_pixel(const XyzImage& image, std::size_t i) {
  return std::isfinite(image.xyz[3 * i]) && std::isfinite(image.xyz[3 * i + 1]) && std::isfinite(image.xyz[3 * i + 2]);
}

Rgb8 pixel_colour(const XyzImage& a, const XyzImage& b, std::size_t i) {
  if (!finite_pixel(a, i) || !finite_pixel(b, i)) return kNoRatioGrey;
  const double ya = a.xyz[3 * i + 1], yb = b.xyz[3 * i + 1];
  if (ya <= kDarkLuminance_cd_m2 && yb <= kDarkLuminance_cd_m2) return kNoRatioGrey;
  return ratio_colour(pixel_luminance_ratio(ya, yb));
}

// The legend's rows, top to bottom, at integer magnification `s`.
struct LegendLayout {
  int s = 1;
  int caption_y, bar_y, bar_height, labels_y, ends_y, swatch_y, height;
  explicit LegendLayout(int scale) : s(scale) {
    caption_y = kMargin * s;
    bar_y = caption_y + text_height(s) + 2 * s;
    bar_height = 12 * s;
    labels_y = bar_y + bar_height + 5 * s;
    ends_y = labels_y + text_height(s);
    swatch_y = ends_y + text_height(s) + 2 * s;
    height = swatch_y + text_height(s) + kMargin * s;
  }
  int bar_x() const { return kMargin * s; }
  int bar_width() const { return kLegendBarWidth * s; }
  int width() const { return bar_width() + 2 * kMargin * s; }
  // x of the ratio's place on the bar (log scale).
  double x_of(double ratio) const {
    const double t = std::log(ratio / kRatioMapLowest) / std::log(kRatioMapHighest / kRatioMapLowest);
    return bar_x() + t * bar_width();
  }
};

void draw_legend(Raster& raster, int top, const LegendLayout& l) {
  const Rgb8 ink{40, 40, 40};
  draw_text(raster, l.bar_x(), top + l.caption_y, "luminance ratio B/A per pixel (log scale)", ink, l.s);
  for (int i = 0; i < l.bar_width(); ++i) {
    const double t = (i + 0.5) / l.bar_width();
    const double ratio = kRatioMapLowest * std::pow(kRatioMapHighest / kRatioMapLowest, t);
    fill_rect(raster, l.bar_x() + i, top + l.bar_y, 1, l.bar_height, ratio_colour(ratio));
  }
  struct Tick {
    double ratio;
    const char* label;
  };
  for (const Tick tick : {Tick{0.5, "1/2"}, Tick{1 / std::sqrt(2.0), "0.71"}, Tick{1.0, "1"},
                          Tick{std::sqrt(2.0), "1.41"}, Tick{2.0, "2"}}) {
    const int x = std::min(static_cast<int>(std::lround(l.x_of(tick.ratio))), l.bar_x() + l.bar_width() - l.s);
    fill_rect(raster, x, top + l.bar_y + l.bar_height, l.s, 3 * l.s, ink);
    const int w = text_width(tick.label, l.s);
    draw_text(raster, std::clamp(x - w / 2, 0, raster.width - w), top + l.labels_y, tick.label, ink, l.s);
  }
  draw_text(raster, l.bar_x(), top + l.ends_y, "B darker", ink, l.s);
  draw_text(raster, l.bar_x() + l.bar_width() - text_width("B brighter", l.s), top + l.ends_y, "B brighter", ink, l.s);
  const int swatch = text_height(l.s) - 2 * l.s;
  fill_rect(raster, l.bar_x(), top + l.swatch_y + l.s, swatch, swatch, kNoRatioGrey);
  draw_text(raster, l.bar_x() + swatch + 4 * l.s, top + l.swatch_y, "both below 1e-4 cd/m²", ink, l.s);
}

}  // namespace

Rgb8 ratio_colour(double ratio) {
  if (!(ratio > 0)) return kCoolWarmBlue;  // 0 (B black, A lit) is as dark as it gets
  return cool_warm(std::log(ratio / kRatioMapLowest) / std::log(kRatioMapHighest / kRatioMapLowest));
}

Raster render_ratio_map(const XyzImage& a, const XyzImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("render_ratio_map: images of " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + " pixels");
  const LegendLayout legend(std::max(1, a.width / 512));
  Raster raster(std::max(a.width, legend.width()), a.height + legend.height, kWhite);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      set_pixel(raster, x, y, pixel_colour(a, b, static_cast<std::size_t>(y) * a.width + x));
  draw_legend(raster, a.height, legend);
  return raster;
}

void write_ratio_map(const XyzImage& a, const XyzImage& b, const std::filesystem::path& path) {
  figure_extension(path, {".png"}, "a ratio map");
  write_png(render_ratio_map(a, b), path);
}

}  // namespace skylit
