// Exact Fresnel reflectances (see fresnel.h for the sources).
#include "skylit/material/fresnel.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

FresnelSP fresnel_sp(double cos_incident, std::complex<double> eta) {
  using C = std::complex<double>;
  // η = 1 is no interface at all: nothing is reflected at any angle. The formula
  // below would divide 0 by 0 at grazing incidence (cos θ_i = cos θ_t = 0; issue 19, item 3).
  if (eta == C(1.0)) return {0.0, 0.0};
  const double cos_i = std::clamp(cos_incident, 0.0, 1.0);
  const double sin2_i = 1.0 - cos_i * cos_i;
  // Snell's law with a complex index: sin θ_t = sin θ_i / η. The principal square
  // root gives the transmitted wave that decays into the medium (for a conductor)
  // and the evanescent one under total internal reflection (|r| = 1 then).
  const C sin2_t = sin2_i / (eta * eta);
  const C cos_t = std::sqrt(C(1.0) - sin2_t);
  const C r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const C r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return {std::norm(r_s), std::norm(r_p)};
}

double fresnel_normal_incidence(std::complex<double> eta) {
  const double n = eta.real(), k = eta.imag();
  return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
}

PaneOptics pane_optics(double cos_incident, double n, double k, double thickness_m, double wavelength_nm) {
  const double cos_i = std::clamp(cos_incident, 0.0, 1.0);
  const FresnelSP r = fresnel_sp(cos_i, n);
  const double sin2_t = (1.0 - cos_i * cos_i) / (n * n);
  const double cos_t = std::sqrt(std::max(0.0, 1.0 - sin2_t));
  const double alpha_per_m = 4.0 * kPi * k / (wavelength_nm * 1e-9);
  const double tau = cos_t > 0 ? std::exp(-alpha_per_m * thickness_m / cos_t) : 0.0;
  PaneOptics out;
  for (const double rj : {r.s, r.p}) {
    const double denominator = 1.0 - rj * rj * tau * tau;
    if (denominator <= 1e-300) {  // grazing: the first surface reflects everything
      out.reflectance += 0.5;
      continue;
    }
    out.reflectance += 0.5 * (rj + (1 - rj) * (1 - rj) * rj * tau * tau / denominator);
    out.transmittance += 0.5 * ((1 - rj) * (1 - rj) * tau / denominator);
  }
  return out;
}

}  // namespace skylit
