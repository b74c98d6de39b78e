// Multiple scattering after Hillaire (2020), "A scalable and production ready sky and
// atmosphere rendering technique", §5.5: at each altitude and sun zenith angle, the
// light scattered twice (isotropically) toward a point, Ψ₂, and the fraction f_ms of
// light that one more isotropic scattering event returns there; all higher orders then
// form the geometric series Ψ_ms = Ψ₂ (1 + f_ms + f_ms² + …) = Ψ₂ / (1 − f_ms). At a
// point with scattering coefficient σ_s the multiply scattered radiance per unit solar
// irradiance is σ_s·Ψ_ms, added to single scattering along view rays.
#pragma once

#include <vector>

#include "skylit/atmosphere/transmittance_table.h"
#include "skylit/spectrum/spectrum_grid.h"

namespace skylit {

class MultipleScatteringTable {
 public:
  static constexpr int kMuSunSize = 40, kAltitudeSize = 16;
  static constexpr int kDirections = 64;  // Hillaire's 64 directions over the sphere
  static constexpr int kSegments = 20;

  MultipleScatteringTable(const AtmosphereMedium& medium, const TransmittanceTable& transmittance,
                          double ground_albedo);

  // Ψ_ms (sr⁻¹ per unit solar irradiance) at radius r with the sun at zenith cosine μ_s.
  Spectrum psi(double r, double mu_sun) const;

  // The two factors at one point, for tests: Ψ₂ and f_ms (both per bin).
  struct Factors {
    Spectrum second_order;  // Ψ₂
    Spectrum transfer;      // f_ms
  };
  static Factors factors_at(const AtmosphereMedium& medium, const TransmittanceTable& transmittance,
                            double ground_albedo, double r, double mu_sun, int directions = kDirections,
                            int segments = kSegments);

 private:
  double ground_radius_, top_radius_;
  SpectrumGrid2D table_;  // x: μ_s, y: altitude
};

}  // namespace skylit
