// The CIE 1931 2° standard observer (data/cie1931_2deg_cmf.csv) and the conversion of
// binned spectra to absolute tristimulus values: Y is luminance in cd/m² for a
// radiance (illuminance in lx for an irradiance), 683 lm/W × ∫ L(λ) ȳ(λ) dλ.
#pragma once

#include <vector>

#include "skylit/spectrum/color_space.h"
#include "skylit/spectrum/radiometry.h"
#include "skylit/spectrum/spectrum.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {

inline constexpr double kMaxLuminousEfficacy = 683.0;  // lm/W at 555 nm (CIE, SI candela)

struct ColourMatchingFunctions {
  Tabulated x, y, z;
};
const ColourMatchingFunctions& cie1931();

// ∫ x̄ dλ, ∫ ȳ dλ, ∫ z̄ dλ over each bin of a grid (nm), so that a spectrum given by
// its bin means integrates against the observer without losing the CMF's shape.
struct CmfBinIntegrals {
  std::vector<double> x, y, z;
};
CmfBinIntegrals cmf_bin_integrals(const WavelengthGrid& grid);

// Relative tristimulus values Σ s_b ∫_b cmf (no 683 factor) on any grid: for colour
// measurements and the bin-count study.
Xyz tristimulus(const std::vector<double>& bin_means, const CmfBinIntegrals& cmf);

// Absolute XYZ of a spectral radiance (W m⁻² sr⁻¹ nm⁻¹ → Y in cd/m²) or of a spectral
// irradiance (W m⁻² nm⁻¹ → Y in lx).
Xyz xyz_from_spectrum(const Spectrum& spectrum);
double luminance(const Spectrum& radiance);
// cd/m² of a radiance, lx of an irradiance (683 lm/W × ∫ · ȳ dλ).
inline double luminance(const Radiance& radiance) { return luminance(radiance.spectrum()); }
inline double illuminance(const Irradiance& irradiance) { return luminance(irradiance.spectrum()); }

}  // namespace skylit
