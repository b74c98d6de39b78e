// Raster drawing primitives (raster.h) and PNG output through image_encoders.h and an
// AtomicFile, so figures share the image writers' checked path to disk.
#include "skylit/figures/raster.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "skylit/figures/figure_file.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image_encoders.h"

namespace skylit {

Raster::Raster(int w, int h, Rgb8 background) : width(w), height(h) {
  if (w < 0 || h < 0) throw std::invalid_argument("Raster: negative size");
  rgb.resize(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  fill(*this, background);
}

Rgb8 Raster::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height)
    throw std::out_of_range("Raster: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") outside " +
                            std::to_string(width) + "x" + std::to_string(height));
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void fill(Raster& raster, Rgb8 colour) {
  for (std::size_t i = 0; i + 2 < raster.rgb.size(); i += 3) {
    raster.rgb[i] = colour.r;
    raster.rgb[i + 1] = colour.g;
    raster.rgb[i + 2] = colour.b;
  }
}

void set_pixel(Raster& raster, int x, int y, Rgb8 colour) {
  if (x < 0 || y < 0 || x >= raster.width || y >= raster.height) return;
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * raster.width + x);
  raster.rgb[i] = colour.r;
  raster.rgb[i + 1] = colour.g;
  raster.rgb[i + 2] = colour.b;
}

void blend_pixel(Raster& raster, int x, int y, Rgb8 colour, double coverage) {
  if (x < 0 || y < 0 || x >= raster.width || y >= raster.height || !(coverage > 0)) return;
  const double a = std::min(coverage, 1.0);
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * raster.width + x);
  const uint8_t c[3] = {colour.r, colour.g, colour.b};
  for (int k = 0; k < 3; ++k)
    raster.rgb[i + k] = static_cast<uint8_t>(std::lround(raster.rgb[i + k] + a * (c[k] - raster.rgb[i + k])));
}

void fill_rect(Raster& raster, int x, int y, int w, int h, Rgb8 colour) {
  const int x0 = std::max(x, 0), x1 = std::min<long long>(static_cast<long long>(x) + w, raster.width);
  const int y0 = std::max(y, 0), y1 = std::min<long long>(static_cast<long long>(y) + h, raster.height);
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) set_pixel(raster, i, j, colour);
}

namespace {

// Distance from p to the segment a–b.
double distance_to_segment(PointF p, PointF a, PointF b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

bool finite(PointF p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

void draw_polyline(Raster& raster, std::span<const PointF> points, Rgb8 colour, double width_px) {
  if (raster.width == 0 || raster.height == 0 || !(width_px > 0)) return;
  const double half = 0.5 * width_px;
  const double reach = half + 0.5;  // beyond this a pixel centre gets no coverage
  // The pixels the stroke can touch: the points' bounding box grown by `reach`, clipped.
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const PointF& p : points)
    if (finite(p)) {
      lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
      lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
    }
  if (!(lo_x <= hi_x) || hi_x + reach < 0 || hi_y + reach < 0 || lo_x - reach > raster.width ||
      lo_y - reach > raster.height)
    return;
  const int box_x = std::max(0, int(std::floor(lo_x - reach)));
  const int box_y = std::max(0, int(std::floor(lo_y - reach)));
  const int box_w = std::min(raster.width, int(std::ceil(std::min(hi_x + reach, double(raster.width))))) - box_x;
  const int box_h = std::min(raster.height, int(std::ceil(std::min(hi_y + reach, double(raster.height))))) - box_y;
  // Coverage in that box, the largest over all segments, blended once at the end.
  std::vector<float> coverage(static_cast<std::size_t>(box_w) * box_h, 0.0f);
  const auto stroke = [&](PointF a, PointF b) {
    const int x0 = std::max(box_x, int(std::floor(std::min(a.x, b.x) - reach)));
    const int x1 = std::min(box_x + box_w - 1, int(std::ceil(std::max(a.x, b.x) + reach)));
    const int y0 = std::max(box_y, int(std::floor(std::min(a.y, b.y) - reach)));
    const int y1 = std::min(box_y + box_h - 1, int(std::ceil(std::max(a.y, b.y) + reach)));
    for (int j = y0; j <= y1; ++j)
      for (int i = x0; i <= x1; ++i) {
        const double d = distance_to_segment({i + 0.5, j + 0.5}, a, b);
        const float c = static_cast<float>(std::clamp(half + 0.5 - d, 0.0, 1.0));
        float& slot = coverage[static_cast<std::size_t>(j - box_y) * box_w + (i - box_x)];
        slot = std::max(slot, c);
      }
  };
  // A non-finite point breaks the line; a lone finite point is drawn as a dot.
  const PointF* previous = nullptr;
  for (const PointF& p : points) {
    if (!finite(p)) {
      previous = nullptr;
      continue;
    }
    stroke(previous ? *previous : p, p);
    previous = &p;
  }
  for (int j = 0; j < box_h; ++j)
    for (int i = 0; i < box_w; ++i)
      blend_pixel(raster, box_x + i, box_y + j, colour, coverage[static_cast<std::size_t>(j) * box_w + i]);
}

void draw_line(Raster& raster, PointF from, PointF to, Rgb8 colour, double width_px) {
  const PointF points[] = {from, to};
  draw_polyline(raster, points, colour, width_px);
}

void blit_rgb8(Raster& raster, int x, int y, int w, int h, std::span<const uint8_t> rgb) {
  if (w < 0 || h < 0 || rgb.size() != 3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h))
    throw std::invalid_argument("blit_rgb8: " + std::to_string(rgb.size()) + " bytes for a " + std::to_string(w) + "x" +
                                std::to_string(h) + " image");
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t s = 3 * (static_cast<std::size_t>(j) * w + i);
      set_pixel(raster, x + i, y + j, {rgb[s], rgb[s + 1], rgb[s + 2]});
    }
}

void write_png(const Raster& raster, const std::filesystem::path& path) {
  figure_extension(path, {".png"}, "a raster figure");
  if (raster.width <= 0 || raster.height <= 0 ||
      raster.rgb.size() != 3 * static_cast<std::size_t>(raster.width) * raster.height)
    throw std::invalid_argument("write_png: malformed raster for \"" + path.string() + "\"");
  AtomicFile file(path);
  file.commit(encode_png_rgb8(raster.width, raster.height, raster.rgb));
}

}  // namespace skylit
