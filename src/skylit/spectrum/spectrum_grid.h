// Tables of spectra on regular grids in 2 and 3 dimensions, read by multilinear
// interpolation at fractional grid coordinates (clamped to the grid).
#pragma once

#include <algorithm>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "skylit/core/huge_pages.h"
#include "skylit/spectrum/spectral_math.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

class SpectrumGrid2D {
 public:
  SpectrumGrid2D(int size_x, int size_y)
      : size_x_(size_x), size_y_(size_y), cells_(static_cast<size_t>(size_x * size_y)) {}

  int size_x() const { return size_x_; }
  int size_y() const { return size_y_; }
  Spectrum& at(int x, int y) { return cells_[static_cast<size_t>(y * size_x_ + x)]; }
  const Spectrum& at(int x, int y) const { return cells_[static_cast<size_t>(y * size_x_ + x)]; }

  // At grid coordinates (fx, fy): 0 is the first sample, size − 1 the last.
  Spectrum interpolate(double fx, double fy) const {
    const auto [x, y, a, b] = cell_at(fx, fy);
    const Spectrum& p00 = at(x, y);
    const Spectrum& p10 = at(x + 1, y);
    const Spectrum& p01 = at(x, y + 1);
    const Spectrum& p11 = at(x + 1, y + 1);
    Spectrum out;
    for (int k = 0; k < kSpectralBins; ++k)
      out[k] = (1 - b) * ((1 - a) * p00[k] + a * p10[k]) + b * ((1 - a) * p01[k] + a * p11[k]);
    return out;
  }
  // The same in the given bins alone: out[i] is interpolate(fx, fy)[bins[i]].
  void interpolate_bins(double fx, double fy, std::span<const int> bins, std::span<float> out) const {
    const auto [x, y, a, b] = cell_at(fx, fy);
    const Spectrum& p00 = at(x, y);
    const Spectrum& p10 = at(x + 1, y);
    const Spectrum& p01 = at(x, y + 1);
    const Spectrum& p11 = at(x + 1, y + 1);
    for (size_t i = 0; i < bins.size(); ++i) {
      const int k = bins[i];
      out[i] = (1 - b) * ((1 - a) * p00[k] + a * p10[k]) + b * ((1 - a) * p01[k] + a * p11[k]);
    }
  }

 private:
  // The cell holding grid coordinates (fx, fy), clamped to the grid, and the fractions
  // across it.
  struct Cell {
    int x, y;
    float a, b;
  };
  Cell cell_at(double fx, double fy) const {
    fx = std::clamp(fx, 0.0, static_cast<double>(size_x_ - 1));
    fy = std::clamp(fy, 0.0, static_cast<double>(size_y_ - 1));
    const int x = std::min(static_cast<int>(fx), size_x_ - 2), y = std::min(static_cast<int>(fy), size_y_ - 2);
    return {x, y, static_cast<float>(fx - x), static_cast<float>(fy - y)};
  }

  int size_x_, size_y_;
  HugePageVector<Spectrum> cells_;
};

// e^(−τ) in the given bins of a table of optical depths τ, at the grid coordinates
// `at` (out[i] for bins[i]); 0 where there are none (the ray meets the ground or lies in
// the Earth's shadow). The transmittance tables' look-ups in a few bins.
inline void transmittance_in_bins(const SpectrumGrid2D& optical_depth,
                                  const std::optional<std::pair<double, double>>& at, std::span<const int> bins,
                                  std::span<float> out) {
  if (!at) {
    std::fill(out.begin(), out.end(), 0.0f);
    return;
  }
  optical_depth.interpolate_bins(at->first, at->second, bins, out);
  for (float& v : out) v = exp_nonpositive(-v);
}

class SpectrumGrid3D {
 public:
  SpectrumGrid3D(int size_x, int size_y, int size_z)
      : size_x_(size_x), size_y_(size_y), size_z_(size_z), cells_(static_cast<size_t>(size_x * size_y * size_z)) {}

  Spectrum& at(int x, int y, int z) { return cells_[index(x, y, z)]; }
  const Spectrum& at(int x, int y, int z) const { return cells_[index(x, y, z)]; }

  Spectrum interpolate(double fx, double fy, double fz) const {
    fx = std::clamp(fx, 0.0, static_cast<double>(size_x_ - 1));
    fy = std::clamp(fy, 0.0, static_cast<double>(size_y_ - 1));
    fz = std::clamp(fz, 0.0, static_cast<double>(size_z_ - 1));
    const int x = std::min(static_cast<int>(fx), size_x_ - 2), y = std::min(static_cast<int>(fy), size_y_ - 2),
              z = std::min(static_cast<int>(fz), size_z_ - 2);
    const float a = static_cast<float>(fx - x), b = static_cast<float>(fy - y), c = static_cast<float>(fz - z);
    Spectrum out;
    for (int dz = 0; dz <= 1; ++dz)
      for (int dy = 0; dy <= 1; ++dy)
        for (int dx = 0; dx <= 1; ++dx) {
          const float w = (dx ? a : 1 - a) * (dy ? b : 1 - b) * (dz ? c : 1 - c);
          const Spectrum& p = at(x + dx, y + dy, z + dz);
          for (int k = 0; k < kSpectralBins; ++k) out[k] += w * p[k];
        }
    return out;
  }

 private:
  size_t index(int x, int y, int z) const { return static_cast<size_t>((z * size_y_ + y) * size_x_ + x); }
  int size_x_, size_y_, size_z_;
  HugePageVector<Spectrum> cells_;
};

}  // namespace skylit
