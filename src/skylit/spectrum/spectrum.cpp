#include "skylit/spectrum/spectrum.h"

#include <algorithm>
#include <stdexcept>

namespace skylit {

std::vector<double> bin_averages(const Tabulated& table, const WavelengthGrid& grid) {
  std::vector<double> out(static_cast<size_t>(grid.bins));
  for (int i = 0; i < grid.bins; ++i)
    out[static_cast<size_t>(i)] = table.average(grid.lower_nm(i), grid.lower_nm(i + 1));
  return out;
}

Spectrum Spectrum::from_bins(const std::vector<double>& bin_values) {
  if (bin_values.size() != static_cast<size_t>(kSpectralBins))
    throw std::logic_error("Spectrum::from_bins: wrong number of bins");
  Spectrum s;
  for (int i = 0; i < kSpectralBins; ++i) s[i] = static_cast<float>(bin_values[static_cast<size_t>(i)]);
  return s;
}

double Spectrum::mean_value() const {
  double sum = 0;
  for (float v : values_) sum += v;
  return sum / kSpectralBins;
}

float Spectrum::max_value() const {
  float m = values_[0];
  for (float v : values_) m = v > m ? v : m;
  return m;
}

}  // namespace skylit
