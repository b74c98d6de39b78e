// Transmittance from a point in the shell to the top of the atmosphere, tabulated over
// (r, μ) with the parametrisation of Bruneton (2017, "A qualitative and quantitative
// evaluation of 8 clear sky models", and his precomputed_atmospheric_scattering
// reference): dense near the horizon, exact at both boundaries. The table holds optical
// depths, interpolated and then exponentiated: far more accurate than interpolating
// transmittance near the horizon. Only rays that do not meet the ground are tabulated;
// rays that do get 0 (the Earth's shadow).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "skylit/atmosphere/optical_properties.h"
#include "skylit/spectrum/spectrum_grid.h"

namespace skylit {

// Column densities (m) of the three constituents along a ray: ∫ ρ ds for Rayleigh,
// aerosols and ozone (relative densities of optical_properties.h).
struct ColumnDensities {
  double rayleigh = 0, aerosol = 0, ozone = 0;
};

// Quadrature along the ray (r, μ) from its origin over [0, length]; the samples crowd
// toward the ray's lowest point, where the integrand peaks. Exact to about 1e-5 with
// the default sample count (tests/atmosphere/transmittance_test.cpp).
ColumnDensities column_densities(const AtmosphereMedium& medium, double r, double mu, double length, int samples = 64);

class RefractedSunTable;

class TransmittanceTable {
 public:
  static constexpr int kMuSize = 256, kRSize = 128;

  TransmittanceTable(const AtmosphereMedium& medium, double ground_radius_m, double top_radius_m);

  // To the top of the atmosphere from radius r along zenith cosine μ; 0 if the ray
  // meets the ground.
  Spectrum to_top(double r, double mu) const;
  // The sun's light at radius r (per unit extraterrestrial irradiance normal to it) when
  // its true zenith cosine there is μ_s: along the bent ray, with the beam's spreading,
  // when the medium refracts (refracted_sun_table.h), else to_top(r, μ_s).
  Spectrum sun(double r, double mu_sun) const;
  // The same in the given bins alone: out[i] is sun(r, μ_s)[bins[i]].
  void sun_in_bins(double r, double mu_sun, std::span<const int> bins, std::span<float> out) const;

  double ground_radius() const { return ground_radius_; }
  double top_radius() const { return top_radius_; }

 private:
  double ground_radius_, top_radius_;
  double horizon_distance_;  // √(top² − ground²): from the ground to the top along the horizon
  SpectrumGrid2D table_;     // optical depth; x: μ, y: r
  std::shared_ptr<const RefractedSunTable> refracted_;  // null: straight rays
  // The table's grid coordinates (x, y) of a ray from r along μ; none if it meets the ground.
  std::optional<std::pair<double, double>> place(double r, double mu) const;
};

}  // namespace skylit
