// The fog's phase function F(θ) of Eq. 12 (sr⁻¹, normalised to 1 over the sphere), of
// the scattering angle θ between the sunlight's direction of travel and the direction
// toward the viewer; cos θ = V·L for the view direction V and the direction L to the sun.
//
// Water droplets of fog (diameters 5–50 µm) scatter with a sharp forward diffraction
// peak, a broad forward body and a rise toward the back (the fog bow and glory). One
// Henyey–Greenstein lobe cannot have all three; Jendersie & d'Eon (2023), "An
// Approximate Mie Scattering Function for Fog and Cloud Rendering", SIGGRAPH Talks,
// doi:10.1145/3587421.3595409, fitted a blend of HG and Draine's (2003) phase function
// to Mie theory for droplet diameters d of 5–50 µm. docs/fog.md gives the mean cosines.
#pragma once

#include <cmath>

#include "skylit/atmosphere/phase_functions.h"

namespace skylit {

// Draine (2003), ApJ 598, 1017, Eq. 4: HG times (1 + α cos²θ), normalised.
inline double draine_phase(double cos_theta, double g, double alpha) {
  return henyey_greenstein_phase(cos_theta, g) * (1.0 + alpha * cos_theta * cos_theta) /
         (1.0 + alpha * (1.0 + 2.0 * g * g) / 3.0);
}

// Jendersie & d'Eon's parameters as functions of the droplet diameter (µm); the fit holds
// for 5 ≤ d ≤ 50.
struct DropletPhaseParameters {
  double g_hg, g_draine, alpha, draine_weight;

  static DropletPhaseParameters for_diameter(double d_um) {
    return {std::exp(-0.0990567 / (d_um - 1.67154)), std::exp(-2.20679 / (d_um + 3.91029) - 0.428934),
            std::exp(3.62489 - 8.29288 / (d_um + 5.52825)), std::exp(-0.599085 / (d_um - 0.641583) - 0.665888)};
  }
};

// (1 − w_D)·HG(g_HG) + w_D·Draine(g_D, α).
inline double droplet_phase(double cos_theta, const DropletPhaseParameters& p) {
  return (1.0 - p.draine_weight) * henyey_greenstein_phase(cos_theta, p.g_hg) +
         p.draine_weight * draine_phase(cos_theta, p.g_draine, p.alpha);
}

// Mean cosine of Draine's function (his Eq. 5) and so of the blend: what one HG lobe
// would need as g to carry the same forward bias.
inline double droplet_phase_mean_cosine(const DropletPhaseParameters& p) {
  const double g = p.g_draine, a = p.alpha;
  const double draine = g * (1.0 + a * (3.0 + 2.0 * g * g) / 5.0) / (1.0 + a * (1.0 + 2.0 * g * g) / 3.0);
  return (1.0 - p.draine_weight) * p.g_hg + p.draine_weight * draine;
}

}  // namespace skylit
