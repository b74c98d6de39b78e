// Rows of a table over the sun's zenith cosine μ_s, crowded (4×) toward the horizon,
// where light scattered in the air changes fastest as the sun sets:
// μ_s = s (¼ + ¾|s|), s = 2x − 1, x ∈ [0, 1].
#pragma once

#include <algorithm>
#include <cmath>

namespace skylit {

inline double mu_sun_from_unit(double x) {
  const double s = 2.0 * x - 1.0;
  return s * (0.25 + 0.75 * std::abs(s));
}

// In double, or in float where a table's weights need no more.
template <typename Real>
Real unit_from_mu_sun(Real mu_sun) {
  const Real m = std::clamp(std::abs(mu_sun), Real(0), Real(1));
  const Real s = (Real(-0.25) + std::sqrt(Real(0.0625) + Real(3) * m)) / Real(1.5);
  return Real(0.5) * (Real(1) + (mu_sun < 0 ? -s : s));
}

}  // namespace skylit
