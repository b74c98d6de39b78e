// The delta-Eddington slab (cloud_two_stream.h) in closed form. With ω = 1 the two moment
// equations integrate directly:
//   I1(τ) = C1 − a μ0 e^{−τ/μ0},   I0(τ) = C0 − (1 − g) C1 τ − a μ0² e^{−τ/μ0},   a = 3/(4π) E0,
// and the two boundary conditions (no diffuse light entering from outside for the sun's
// field) fix C0 and C1:
//   top:    C0 + 2/3 C1 = a μ0² + 2/3 a μ0
//   bottom: C0 − ((1 − g) τ_c + 2/3) C1 = a μ0² e_c − 2/3 a μ0 e_c,   e_c = e^{−τ_c/μ0}.
// A diffuse irradiance E on a face instead: π(I0 + 2/3 I1) = E on the top, π(I0 − 2/3 I1)
// = E on the bottom, and no source inside, so I1 is constant and I0 linear.
#include "skylit/clouds/cloud_two_stream.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

constexpr double kA = 3.0 / (4.0 * kPi);  // 3/(4π)

}  // namespace

DeltaScaling::DeltaScaling(double g) : forward_fraction(g * g), asymmetry(g / (1 + g)) {}

EddingtonField eddington_sun_field(double depth, double g, double mu0, double tau) {
  if (!(mu0 > 0) || !(depth > 0)) return {};
  tau = std::clamp(tau, 0.0, depth);
  const double e_c = std::exp(-depth / mu0), e = std::exp(-tau / mu0);
  const double c1 = (kA * mu0 * mu0 * (1 - e_c) + (2.0 / 3.0) * kA * mu0 * (1 + e_c)) / ((1 - g) * depth + 4.0 / 3.0);
  const double c0 = kA * mu0 * mu0 + (2.0 / 3.0) * kA * mu0 - (2.0 / 3.0) * c1;
  return {c0 - (1 - g) * c1 * tau - kA * mu0 * mu0 * e, c1 - kA * mu0 * e};
}

EddingtonField eddington_diffuse_field(double depth, double g, double tau, bool from_top) {
  depth = std::max(depth, 0.0);
  tau = std::clamp(tau, 0.0, depth);
  // The flux runs from the lit face to the other: I1 > 0 (downward) when lit from the top.
  const double c1 = (from_top ? 1.0 : -1.0) / (kPi * ((1 - g) * depth + 4.0 / 3.0));
  const double c0 = (from_top ? 1.0 : 0.0) / kPi - (2.0 / 3.0) * c1;
  return {c0 - (1 - g) * c1 * tau, c1};
}

double eddington_sun_albedo(double depth, double g, double mu0) {
  if (!(mu0 > 0)) return 0.0;
  // π(I0 − 2/3 I1) at the top, over μ0 (E0 = 1).
  const EddingtonField top = eddington_sun_field(depth, g, mu0, 0.0);
  return kPi * (top.mean - (2.0 / 3.0) * top.flux) / mu0;
}

}  // namespace skylit
