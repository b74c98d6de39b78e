#include "skylit/atmosphere/air_density_profile.h"

#include <algorithm>
#include <cmath>

#include "skylit/spectrum/tabulated.h"

namespace skylit {

namespace {
constexpr double kRowSpacingM = 1000.0;  // the table's rows are 1 km apart, from 0 km
}

AirDensityProfile AirDensityProfile::us_standard_1976() {
  static const AirDensityProfile profile = [] {
    const Tabulated table = embedded_table("us_standard_atmosphere_1976.csv", 1);
    AirDensityProfile p;
    for (double ratio : table.y) p.log_density_.push_back(std::log(ratio));
    // Exact for a density exponential within each row: Δh (ρ_a − ρ_b) / ln(ρ_a/ρ_b).
    double column = 0;
    for (size_t i = 0; i + 1 < p.log_density_.size(); ++i) {
      const double a = p.log_density_[i], b = p.log_density_[i + 1];
      column += kRowSpacingM * (std::exp(a) - std::exp(b)) / (a - b);
    }
    const double top_slope = p.log_density_.back() - p.log_density_[p.log_density_.size() - 2];
    column += std::exp(p.log_density_.back()) * kRowSpacingM / -top_slope;  // the tail above
    p.equivalent_height_m_ = column;
    return p;
  }();
  return profile;
}

AirDensityProfile AirDensityProfile::exponential(double scale_height_m) {
  AirDensityProfile p;
  p.scale_height_m_ = scale_height_m;
  p.equivalent_height_m_ = scale_height_m;
  return p;
}

double AirDensityProfile::relative_density(double altitude_m) const {
  if (scale_height_m_ > 0) return std::exp(-altitude_m / scale_height_m_);  // the paper's Eq. (1)
  // Outside the table (below sea level, above 86 km) the nearest row's slope continues.
  const double x = altitude_m / kRowSpacingM;
  const size_t i = x <= 0 ? 0 : std::min(static_cast<size_t>(x), log_density_.size() - 2);
  const double t = x - static_cast<double>(i);
  return std::exp(log_density_[i] + t * (log_density_[i + 1] - log_density_[i]));
}

}  // namespace skylit
