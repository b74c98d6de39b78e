// Phase functions, normalised to 1 over the sphere (sr⁻¹), of the angle θ between the
// directions of incidence and scattering, given as cos θ.
#pragma once

#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

inline constexpr double kFourPi = 4.0 * kPi;

// Rayleigh scattering with molecular anisotropy (Chandrasekhar 1950): γ = ρ/(2 − ρ)
// for the depolarisation ratio ρ; γ = 0 gives the textbook 3/(16π)(1 + cos²θ).
inline double rayleigh_phase(double cos_theta, double gamma) {
  return 3.0 / (4.0 * (1.0 + 2.0 * gamma)) * ((1.0 + 3.0 * gamma) + (1.0 - gamma) * cos_theta * cos_theta) / kFourPi;
}

// Henyey & Greenstein (1941).
inline double henyey_greenstein_phase(double cos_theta, double g) {
  const double denom = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (kFourPi * denom * std::sqrt(denom));
}

// Cornette & Shanks (1992): Henyey–Greenstein made closer to Mie for haze, with a
// Rayleigh-like term; g is its parameter (close to the mean cosine).
inline double cornette_shanks_phase(double cos_theta, double g) {
  const double denom = 1.0 + g * g - 2.0 * g * cos_theta;
  return 3.0 / (8.0 * kPi) * (1.0 - g * g) * (1.0 + cos_theta * cos_theta) / ((2.0 + g * g) * denom * std::sqrt(denom));
}

}  // namespace skylit
