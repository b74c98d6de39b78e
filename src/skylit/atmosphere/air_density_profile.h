// The air's density against altitude, relative to sea level: the US Standard
// Atmosphere 1976 (data/us_standard_atmosphere_1976.csv) or the paper's exponential
// (Eq. 1). Twilight's light is scattered 20–60 km up, where the two differ by 1.5–2.3
// times (docs/atmosphere.md, "Twilight").
#pragma once

#include <vector>

namespace skylit {

class AirDensityProfile {
 public:
  // The US Standard Atmosphere 1976, log-linear between its 1 km rows; above its last
  // row (86 km) the last row's scale height continues.
  static AirDensityProfile us_standard_1976();
  static AirDensityProfile exponential(double scale_height_m);

  double relative_density(double altitude_m) const;
  // ∫₀^∞ relative_density dh (m): the height of a column of sea-level air holding the
  // same molecules, which turns a column optical depth into a sea-level coefficient.
  double equivalent_height_m() const { return equivalent_height_m_; }

 private:
  AirDensityProfile() = default;

  double scale_height_m_ = 0;        // > 0: exponential; else the table
  std::vector<double> log_density_;  // ln(ρ/ρ₀) at 0, 1, 2, ... km
  double equivalent_height_m_ = 0;
};

}  // namespace skylit
