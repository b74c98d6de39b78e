// The spectral power distribution of a lamp, as the renderer needs it: a spectrum of
// radiant intensity per candela, so that a luminaire's photometry (candela from its
// file or shape) times this spectrum is its spectral radiant intensity in
// W sr⁻¹ nm⁻¹ with exactly the luminous intensity the photometry says:
// 683 lm/W · Σ_b S_b ∫_b ȳ dλ = 1 cd per candela (the same binned observer the
// renderer's output uses, so a 1000 cd lamp gives 40 lx at 5 m in the image too).
//
// Lamp types and where their spectra come from (docs/lights.md, data/SOURCES.md):
//   high_pressure_sodium      CIE HP1, standard high-pressure sodium, 1959 K (CIE 15:2004)
//   colour_enhanced_sodium    CIE HP2, colour-enhanced high-pressure sodium, 2506 K
//   metal_halide              CIE HP3, metal halide, 3144 K
//   metal_halide_4000k        CIE HP4, metal halide, 4002 K
//   metal_halide_hp5          CIE HP5, metal halide, 4039 K
//   led                       phosphor-converted white LED at a CCT: the CIE 015:2018
//                             LED-B1…B5 spectra (2733–6598 K) mixed in reciprocal
//                             colour temperature between the two that bracket it
//   halogen, incandescent     Planck's law at the filament temperature (halogen
//                             3000 K, incandescent 2856 K as CIE illuminant A)
//   blackbody                 Planck's law at a given temperature
//   table                     a user's table of relative spectral power
#pragma once

#include <string>

#include "skylit/spectrum/spectrum.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {

enum class LampType {
  kHighPressureSodium,
  kColourEnhancedSodium,
  kMetalHalide,
  kMetalHalide4000K,
  kMetalHalideHp5,
  kLed,
  kHalogen,
  kIncandescent,
  kBlackbody,
  kTable,
};

// The CCT range the CIE LED-B spectra span (K); an LED outside it has no spectrum here.
inline constexpr double kLedMinCctK = 2733.0;
inline constexpr double kLedMaxCctK = 6598.0;
inline constexpr double kHalogenTemperatureK = 3000.0;
inline constexpr double kIncandescentTemperatureK = 2856.0;

struct LampSpectrumSettings {
  LampType type = LampType::kLed;
  double temperature_k = 4000.0;  // the LED's CCT, or the blackbody's temperature
  Tabulated table;                // for kTable: relative spectral power against nm
};

// The scene file's word for each type ("high_pressure_sodium", "led", ...), and back
// (false for an unknown word).
std::string lamp_type_name(LampType type);
bool lamp_type_from_name(const std::string& name, LampType& type);

// Planck's law: spectral radiance of a blackbody at `temperature_k`, W m⁻² sr⁻¹ nm⁻¹.
double planck_radiance(double wavelength_nm, double temperature_k);

// Spectral radiant intensity per candela (W sr⁻¹ nm⁻¹ cd⁻¹) in each bin.
// Throws std::invalid_argument for a temperature out of range (LED: kLedMinCctK to
// kLedMaxCctK; blackbody 500–25,000 K) or a table without luminous power in 380–780 nm.
Spectrum lamp_spectrum_per_candela(const LampSpectrumSettings& settings);

}  // namespace skylit
