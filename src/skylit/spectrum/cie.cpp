#include "skylit/spectrum/cie.h"

namespace skylit {

const ColourMatchingFunctions& cie1931() {
  static const ColourMatchingFunctions cmf{embedded_table("cie1931_2deg_cmf.csv", 1),
                                           embedded_table("cie1931_2deg_cmf.csv", 2),
                                           embedded_table("cie1931_2deg_cmf.csv", 3)};
  return cmf;
}

CmfBinIntegrals cmf_bin_integrals(const WavelengthGrid& grid) {
  const ColourMatchingFunctions& cmf = cie1931();
  CmfBinIntegrals out{bin_averages(cmf.x, grid), bin_averages(cmf.y, grid), bin_averages(cmf.z, grid)};
  for (auto* column : {&out.x, &out.y, &out.z})
    for (double& v : *column) v *= grid.width_nm();
  return out;
}

Xyz tristimulus(const std::vector<double>& bin_means, const CmfBinIntegrals& cmf) {
  Xyz xyz;
  for (size_t i = 0; i < bin_means.size(); ++i) {
    xyz.x += bin_means[i] * cmf.x[i];
    xyz.y += bin_means[i] * cmf.y[i];
    xyz.z += bin_means[i] * cmf.z[i];
  }
  return xyz;
}

namespace {
const CmfBinIntegrals& production_cmf() {
  static const CmfBinIntegrals cmf = cmf_bin_integrals(kGrid);
  return cmf;
}
}  // namespace

Xyz xyz_from_spectrum(const Spectrum& spectrum) {
  const CmfBinIntegrals& cmf = production_cmf();
  Xyz xyz;
  for (int i = 0; i < kSpectralBins; ++i) {
    const size_t b = static_cast<size_t>(i);
    xyz.x += spectrum[i] * cmf.x[b];
    xyz.y += spectrum[i] * cmf.y[b];
    xyz.z += spectrum[i] * cmf.z[b];
  }
  return {xyz.x * kMaxLuminousEfficacy, xyz.y * kMaxLuminousEfficacy, xyz.z * kMaxLuminousEfficacy};
}

double luminance(const Spectrum& radiance) {
  // Y alone (as xyz_from_spectrum sums it): the sky-light integrals ask for it per element.
  const CmfBinIntegrals& cmf = production_cmf();
  double y = 0;
  for (int i = 0; i < kSpectralBins; ++i) y += radiance[i] * cmf.y[static_cast<size_t>(i)];
  return y * kMaxLuminousEfficacy;
}

}  // namespace skylit
