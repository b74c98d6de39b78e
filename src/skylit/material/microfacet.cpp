// Beckmann distribution and V-cavity attenuation of Cook & Torrance (1982), in the
// normalised form (microfacet.h explains why).
#include "skylit/material/microfacet.h"

#include <algorithm>
#include <cmath>

namespace skylit {

double beckmann_distribution(double cos_alpha, double m) {
  if (cos_alpha <= 0) return 0;
  const double c2 = cos_alpha * cos_alpha;
  const double tan2 = (1 - c2) / c2;
  return std::exp(-tan2 / (m * m)) / (kPi * m * m * c2 * c2);
}

double v_cavity_geometry(const Vec3& n, const Vec3& h, const Vec3& to_light, const Vec3& to_viewer) {
  const double nh = dot(n, h), vh = dot(to_viewer, h);
  if (vh <= 0) return 0;
  const double masking = 2 * nh * dot(n, to_viewer) / vh;
  const double shadowing = 2 * nh * dot(n, to_light) / vh;
  return std::max(0.0, std::min({1.0, masking, shadowing}));
}

MicrofacetTerm cook_torrance_term(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer, double m) {
  const double nl = dot(n, to_light), nv = dot(n, to_viewer);
  if (nl <= 0 || nv <= 0) return {};
  const Vec3 sum = to_light + to_viewer;
  const double len = length(sum);
  if (len <= 0) return {};  // light and viewer opposite: cannot both be above the surface
  const Vec3 h = sum / len;
  const double d = beckmann_distribution(dot(n, h), m);
  const double g = v_cavity_geometry(n, h, to_light, to_viewer);
  return {d * g / (4 * nl * nv), std::clamp(dot(to_viewer, h), 0.0, 1.0)};
}

double beckmann_half_angle_at_1e3(double m) {
  // D(α)/D(0) = exp(−tan²α/m²) / cos⁴α = 1e-3  ⇔  tan²α = m² (ln 1000 + 2 ln(1 + tan²α)).
  // The right side grows only logarithmically, so the iteration converges fast.
  double t2 = 0;
  for (int i = 0; i < 50; ++i) t2 = m * m * (std::log(1000.0) + 2 * std::log1p(t2));
  return std::atan(std::sqrt(t2));
}

}  // namespace skylit
