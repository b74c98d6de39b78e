// Veiling glare and acuity for the human display (human_vision_limits.h).
#include "skylit/io/image/human_vision_limits.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

double acuity_cycles_per_degree(double adaptation) {
  return 17.25 * std::atan(1.4 * std::log10(std::max(adaptation, 1e-12)) + 0.35) + 25.72;
}

double grid_at(const std::vector<double>& grid, int gw, int gh, int block, int x, int y) {
  const double gx = std::clamp((x + 0.5) / block - 0.5, 0.0, double(gw - 1));
  const double gy = std::clamp((y + 0.5) / block - 0.5, 0.0, double(gh - 1));
  const int x0 = int(gx), y0 = int(gy), x1 = std::min(x0 + 1, gw - 1), y1 = std::min(y0 + 1, gh - 1);
  const double tx = gx - x0, ty = gy - y0;
  auto at = [&](int i, int j) { return grid[std::size_t(j) * gw + i]; };
  return (1 - ty) * ((1 - tx) * at(x0, y0) + tx * at(x1, y0)) + ty * ((1 - tx) * at(x0, y1) + tx * at(x1, y1));
}

namespace {

// A grid of cells `block` × `block` samples of `fovea` (means over the samples inside).
std::vector<double> coarsened(const std::vector<double>& fovea, int fw, int fh, int block, int& cw, int& ch) {
  cw = (fw + block - 1) / block;
  ch = (fh + block - 1) / block;
  std::vector<double> sum(std::size_t(cw) * ch, 0.0), count(sum.size(), 0.0);
  for (int y = 0; y < fh; ++y)
    for (int x = 0; x < fw; ++x) {
      sum[std::size_t(y / block) * cw + x / block] += fovea[std::size_t(y) * fw + x];
      count[std::size_t(y / block) * cw + x / block] += 1;
    }
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] /= count[i];
  return sum;
}

}  // namespace

std::vector<double> veiling_luminance(const std::vector<double>& fovea, int fw, int fh, double degrees_per_sample) {
  int block = 1;
  while (((fw + block - 1) / block) * ((fh + block - 1) / block) > kMaxVeilSamples) ++block;
  int cw = 0, ch = 0;
  const std::vector<double> cells = coarsened(fovea, fw, fh, block, cw, ch);
  const double cell_rad = radians(degrees_per_sample * block);
  std::vector<double> cell_veil(cells.size(), 0.0);
  for (int iy = 0; iy < ch; ++iy)
    for (int ix = 0; ix < cw; ++ix) {
      double weighted = 0, weights = 0;
      for (int jy = 0; jy < ch; ++jy)
        for (int jx = 0; jx < cw; ++jx) {
          if (jx == ix && jy == iy) continue;
          const double theta = cell_rad * std::hypot(double(jx - ix), double(jy - iy));
          if (theta >= kPi / 2) continue;  // behind the eye's field
          const double w = std::cos(theta) / (theta * theta);
          weighted += w * cells[std::size_t(jy) * cw + jx];
          weights += w;
        }
      // A lone cell has no rest of the field: its own light stands for the veil.
      cell_veil[std::size_t(iy) * cw + ix] =
          kVeilShare * (weights > 0 ? weighted / weights : cells[std::size_t(iy) * cw + ix]);
    }
  if (block == 1) return cell_veil;
  // Back onto the samples, bilinearly between the cells' centres: the veil is smooth,
  // and a cell's constant value would draw the cells.
  std::vector<double> veil(fovea.size());
  for (int y = 0; y < fh; ++y)
    for (int x = 0; x < fw; ++x) veil[std::size_t(y) * fw + x] = grid_at(cell_veil, cw, ch, block, x, y);
  return veil;
}

XyzImage acuity_limited(const XyzImage& image, const std::vector<double>& adaptation, double degrees_per_pixel) {
  const int w = image.width, h = image.height;
  // Summed-area table of X, Y, Z (double: sums of millions of pixels).
  const std::size_t sw = std::size_t(w) + 1;
  std::vector<double> sat(3 * sw * (std::size_t(h) + 1), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = image.xyz[3 * (std::size_t(y) * w + x) + c];
        sat[3 * ((y + 1) * sw + x + 1) + c] = (std::isfinite(v) ? v : 0.0) + sat[3 * (y * sw + x + 1) + c] +
                                              sat[3 * ((y + 1) * sw + x) + c] - sat[3 * (y * sw + x) + c];
      }
  XyzImage out = image;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double width_px = 1.0 / (acuity_cycles_per_degree(adaptation[std::size_t(y) * w + x]) * degrees_per_pixel);
      if (!(width_px >= 1.5)) continue;
      const int r = int(std::lround((std::min(width_px, 4.0 * std::max(w, h)) - 1) / 2));
      const int x0 = std::max(0, x - r), x1 = std::min(w, x + r + 1), y0 = std::max(0, y - r),
                y1 = std::min(h, y + r + 1);
      const double n = double(x1 - x0) * (y1 - y0);
      for (int c = 0; c < 3; ++c) {
        const double sum = sat[3 * (y1 * sw + x1) + c] - sat[3 * (y0 * sw + x1) + c] - sat[3 * (y1 * sw + x0) + c] +
                           sat[3 * (y0 * sw + x0) + c];
        out.xyz[3 * (std::size_t(y) * w + x) + c] = static_cast<float>(sum / n);
      }
    }
  return out;
}

}  // namespace skylit
