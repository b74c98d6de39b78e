// Spectra sampled in fixed wavelength bins across the visible range.
//
// A Spectrum holds, per bin, the mean of a spectral quantity over the bin (radiance
// in W m⁻² sr⁻¹ nm⁻¹, irradiance in W m⁻² nm⁻¹, or a reflectance). The bin count is
// a compile-time constant chosen by measured colour error: docs/spectrum.md gives
// the measurement and tests/spectrum/bin_count_test.cpp checks it.
#pragma once

#include <array>
#include <vector>

#include "skylit/spectrum/tabulated.h"

namespace skylit {

// Bins of equal width between lo_nm and hi_nm.
struct WavelengthGrid {
  int bins;
  double lo_nm;
  double hi_nm;

  constexpr double width_nm() const { return (hi_nm - lo_nm) / bins; }
  constexpr double lower_nm(int i) const { return lo_nm + i * width_nm(); }
  constexpr double center_nm(int i) const { return lo_nm + (i + 0.5) * width_nm(); }
};

// 380–780 nm: outside it the CIE 1931 observer's weights add less than 0.01 % to Y.
inline constexpr double kVisibleMinNm = 380.0;
inline constexpr double kVisibleMaxNm = 780.0;
inline constexpr int kSpectralBins = 40;
inline constexpr WavelengthGrid kGrid{kSpectralBins, kVisibleMinNm, kVisibleMaxNm};

// Means of a tabulated function over each bin of a grid.
std::vector<double> bin_averages(const Tabulated& table, const WavelengthGrid& grid);

class Spectrum {
 public:
  constexpr Spectrum() : values_{} {}
  constexpr explicit Spectrum(float constant) { values_.fill(constant); }
  static Spectrum from_bins(const std::vector<double>& bin_values);
  static Spectrum from_table(const Tabulated& table) { return from_bins(bin_averages(table, kGrid)); }

  static constexpr int size() { return kSpectralBins; }
  constexpr float& operator[](int i) { return values_[static_cast<size_t>(i)]; }
  constexpr float operator[](int i) const { return values_[static_cast<size_t>(i)]; }

  Spectrum& operator+=(const Spectrum& o) {
    for (int i = 0; i < size(); ++i) (*this)[i] += o[i];
    return *this;
  }
  Spectrum& operator-=(const Spectrum& o) {
    for (int i = 0; i < size(); ++i) (*this)[i] -= o[i];
    return *this;
  }
  Spectrum& operator*=(const Spectrum& o) {
    for (int i = 0; i < size(); ++i) (*this)[i] *= o[i];
    return *this;
  }
  Spectrum& operator*=(float s) {
    for (float& v : values_) v *= s;
    return *this;
  }

  float max_value() const;
  // The mean over the bins (in double, bin by bin in order).
  double mean_value() const;
  // max_value() <= 0, stopping at the first positive bin: light is positive in its
  // first bins, and the full scan (a chain of 40 dependent compares) showed at 4–7 % of
  // Fig. 7's and Fig. 8's frames. A NaN first bin is not black, as max_value() has it.
  bool is_black() const {
    if (values_[0] != values_[0]) return false;
    for (float v : values_)
      if (v > 0.0f) return false;
    return true;
  }

 private:
  std::array<float, kSpectralBins> values_;
};

inline Spectrum operator+(Spectrum a, const Spectrum& b) { return a += b; }
inline Spectrum operator-(Spectrum a, const Spectrum& b) { return a -= b; }
inline Spectrum operator*(Spectrum a, const Spectrum& b) { return a *= b; }
inline Spectrum operator*(Spectrum a, float s) { return a *= s; }
inline Spectrum operator*(float s, Spectrum a) { return a *= s; }

}  // namespace skylit
