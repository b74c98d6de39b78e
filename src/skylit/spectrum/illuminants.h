// Light spectra from the data tables: the extraterrestrial sun (Gueymard 2004) and
// CIE D65.
#pragma once

#include "skylit/spectrum/spectrum.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {

// Extraterrestrial solar spectral irradiance at 1 AU, W m⁻² nm⁻¹ (data/solar_extraterrestrial.csv).
const Tabulated& solar_extraterrestrial_table();
Spectrum solar_extraterrestrial_irradiance();

// CIE D65, relative spectral power, 100 at 560 nm (data/cie_d65.csv).
const Tabulated& cie_d65_table();

}  // namespace skylit
