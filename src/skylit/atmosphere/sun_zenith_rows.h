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

inline double unit_from_mu_sun(double mu_sun) {
  const double m = std::clamp(std::abs(mu_sun), 0.0, 1.0);
  const double s = (-0.25 + std::sqrt(0.0625 + 3.0 * m)) / 1.5;
  return 0.5 * (1.0 + (mu_sun < 0 ? -s : s));
}

}  // namespace skylit
