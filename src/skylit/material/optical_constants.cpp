// Complex refractive indices per bin from data/ tables (sources in data/SOURCES.md).
#include "skylit/material/optical_constants.h"

#include "skylit/spectrum/tabulated.h"

namespace skylit {

namespace {

ComplexIor ior_from_csv(std::string_view name) {
  // Columns: wavelength_nm, n, k.
  return {Spectrum::from_table(embedded_table(name, 1)), Spectrum::from_table(embedded_table(name, 2))};
}

}  // namespace

bool ComplexIor::is_conductor() const {
  // k = 0.01 absorbs visible light within about 4 µm: no practical layer of such a
  // medium lets light through to a base below, so it is treated as opaque.
  for (int i = 0; i < Spectrum::size(); ++i)
    if (k[i] > 0.01f) return true;
  return false;
}

const ComplexIor& aluminium_ior() {
  static const ComplexIor ior = ior_from_csv("metal_aluminium_nk.csv");
  return ior;
}

const ComplexIor& soda_lime_glass_ior() {
  static const ComplexIor ior = ior_from_csv("glass_soda_lime_nk.csv");
  return ior;
}

ComplexIor constant_ior(double n, double k) {
  return {Spectrum(static_cast<float>(n)), Spectrum(static_cast<float>(k))};
}

ComplexIor ior_from_samples(const std::vector<IorSample>& samples) {
  Tabulated n, k;
  // Hold the end values: a table zero outside its range would make n = 0 there.
  const auto hold = [&](double wavelength, const IorSample& s) {
    n.x.push_back(wavelength);
    n.y.push_back(s.n);
    k.x.push_back(wavelength);
    k.y.push_back(s.k);
  };
  if (samples.front().wavelength_nm > kVisibleMinNm) hold(kVisibleMinNm - 1.0, samples.front());
  for (const IorSample& s : samples) hold(s.wavelength_nm, s);
  if (samples.back().wavelength_nm < kVisibleMaxNm) hold(kVisibleMaxNm + 1.0, samples.back());
  return {Spectrum::from_table(n), Spectrum::from_table(k)};
}

}  // namespace skylit
