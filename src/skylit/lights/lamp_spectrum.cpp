#include "skylit/lights/lamp_spectrum.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "skylit/spectrum/cie.h"

namespace skylit {

namespace {

struct NamedType {
  const char* name;
  LampType type;
};
constexpr std::array<NamedType, 10> kTypeNames{{
    {"high_pressure_sodium", LampType::kHighPressureSodium},
    {"colour_enhanced_sodium", LampType::kColourEnhancedSodium},
    {"metal_halide", LampType::kMetalHalide},
    {"metal_halide_4000k", LampType::kMetalHalide4000K},
    {"metal_halide_hp5", LampType::kMetalHalideHp5},
    {"led", LampType::kLed},
    {"halogen", LampType::kHalogen},
    {"incandescent", LampType::kIncandescent},
    {"blackbody", LampType::kBlackbody},
    {"table", LampType::kTable},
}};

// The CCTs CIE 015:2018 (Table 10) gives for LED-B1 … LED-B5, columns 1–5 of
// data/lamp_cie_led.csv.
constexpr std::array<double, 5> kLedCctK{2733.0, 2998.0, 4103.0, 5109.0, 6598.0};

// Scaled to one candela: 683 · Σ S_b ∫_b ȳ = 1.
Spectrum per_candela(const Spectrum& relative) {
  const double candela = luminance(relative);
  if (!(candela > 0) || !std::isfinite(candela))
    throw std::invalid_argument("the lamp spectrum has no luminous power in 380–780 nm");
  return relative * static_cast<float>(1.0 / candela);
}

Spectrum blackbody(double temperature_k) {
  if (!(temperature_k >= 500 && temperature_k <= 25000))
    throw std::invalid_argument("a blackbody temperature must be within 500–25000 K");
  // Bin means by Simpson's rule on 1 nm steps: Planck's curve is smooth on that scale.
  std::vector<double> bins(kSpectralBins);
  for (int b = 0; b < kSpectralBins; ++b) {
    const double lo = kGrid.lower_nm(b), width = kGrid.width_nm();
    const int steps = static_cast<int>(std::ceil(width));
    const double h = width / steps;
    double sum = 0;
    for (int i = 0; i < steps; ++i) {
      const double a = lo + i * h;
      sum += h / 6 *
             (planck_radiance(a, temperature_k) + 4 * planck_radiance(a + h / 2, temperature_k) +
              planck_radiance(a + h, temperature_k));
    }
    bins[b] = sum / width;
  }
  return Spectrum::from_bins(bins);
}

Spectrum led(double cct_k) {
  if (!(cct_k >= kLedMinCctK && cct_k <= kLedMaxCctK))
    throw std::invalid_argument("an LED's colour temperature must be within 2733–6598 K (the CIE LED-B spectra)");
  // The two tabulated LEDs around the CCT, mixed (each scaled to one candela) with
  // weights linear in reciprocal temperature, the scale on which CCT differences
  // are roughly equally visible.
  size_t hi = 1;
  while (hi + 1 < kLedCctK.size() && kLedCctK[hi] < cct_k) ++hi;
  const size_t lo = hi - 1;
  const double w = (1 / kLedCctK[lo] - 1 / cct_k) / (1 / kLedCctK[lo] - 1 / kLedCctK[hi]);
  const Spectrum a = per_candela(Spectrum::from_table(embedded_table("lamp_cie_led.csv", static_cast<int>(lo) + 1)));
  const Spectrum b = per_candela(Spectrum::from_table(embedded_table("lamp_cie_led.csv", static_cast<int>(hi) + 1)));
  return a * static_cast<float>(1 - w) + b * static_cast<float>(w);
}

Spectrum cie_discharge_lamp(int column) { return Spectrum::from_table(embedded_table("lamp_cie_hp.csv", column)); }

}  // namespace

std::string lamp_type_name(LampType type) {
  for (const NamedType& n : kTypeNames)
    if (n.type == type) return n.name;
  return "?";
}

bool lamp_type_from_name(const std::string& name, LampType& type) {
  for (const NamedType& n : kTypeNames)
    if (name == n.name) {
      type = n.type;
      return true;
    }
  return false;
}

double planck_radiance(double wavelength_nm, double temperature_k) {
  // CODATA 2018 exact constants.
  constexpr double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
  const double lambda = wavelength_nm * 1e-9;
  const double per_m = 2 * h * c * c / std::pow(lambda, 5) / std::expm1(h * c / (lambda * k * temperature_k));
  return per_m * 1e-9;  // per metre of wavelength → per nanometre
}

Spectrum lamp_spectrum_per_candela(const LampSpectrumSettings& s) {
  switch (s.type) {
    case LampType::kHighPressureSodium:
      return per_candela(cie_discharge_lamp(1));
    case LampType::kColourEnhancedSodium:
      return per_candela(cie_discharge_lamp(2));
    case LampType::kMetalHalide:
      return per_candela(cie_discharge_lamp(3));
    case LampType::kMetalHalide4000K:
      return per_candela(cie_discharge_lamp(4));
    case LampType::kMetalHalideHp5:
      return per_candela(cie_discharge_lamp(5));
    case LampType::kLed:
      return per_candela(led(s.temperature_k));
    case LampType::kHalogen:
      return per_candela(blackbody(kHalogenTemperatureK));
    case LampType::kIncandescent:
      return per_candela(blackbody(kIncandescentTemperatureK));
    case LampType::kBlackbody:
      return per_candela(blackbody(s.temperature_k));
    case LampType::kTable: {
      for (double y : s.table.y)
        if (!(y >= 0) || !std::isfinite(y)) throw std::invalid_argument("a lamp spectrum table needs values ≥ 0");
      return per_candela(Spectrum::from_table(s.table));
    }
  }
  throw std::invalid_argument("unknown lamp type");
}

}  // namespace skylit
