// The sunlight at every point of the shell through the air's refraction
// (refracted_ray.h), tabulated over (r, μ_s) with μ_s the cosine of the sun's true
// (unrefracted) zenith angle at the point, as TransmittanceTable::to_top is for straight
// rays. Each entry holds the optical depth of the bent path plus −ln of the beam's
// spreading: rays that pass lower bend more, so a beam that grazed the Earth fans out
// vertically and its irradiance falls by (sin z_a / sin z_s) · dz_a/dz_s (z_a, z_s the
// apparent and the true zenith angle; the setting sun's flattened disc). Below the edge
// of the refracted shadow, lower than the straight one's, the table gives 0.
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "skylit/atmosphere/optical_properties.h"
#include "skylit/spectrum/spectrum_grid.h"

namespace skylit {

class RefractedSunTable {
 public:
  // Rows in r as TransmittanceTable's; columns in μ_s from the shadow's edge to the
  // zenith, crowded (quadratically) toward the edge. Each row is resampled from
  // kRaysPerRow rays traced from apparent directions crowded toward the grazing one.
  static constexpr int kMuSize = 256, kRSize = 128, kRaysPerRow = 384;

  RefractedSunTable(const AtmosphereMedium& medium, double ground_radius_m, double top_radius_m);

  // Per unit extraterrestrial irradiance normal to the sun: transmittance times spreading.
  Spectrum sunlight(double r, double mu_sun) const;
  // The same in the given bins alone: out[i] is sunlight(r, μ_s)[bins[i]] (the
  // scattering orders' table works in 8 of the 40).
  void sunlight_in_bins(double r, double mu_sun, std::span<const int> bins, std::span<float> out) const;
  // The edge of the Earth's refracted shadow at radius r: the true zenith cosine of the
  // sun whose ray grazes the ground on its way there.
  double shadow_edge_mu(double r) const;

 private:
  double ground_radius_, top_radius_;
  double horizon_distance_;      // √(top² − ground²)
  std::vector<double> edge_mu_;  // shadow_edge_mu per row
  SpectrumGrid2D table_;         // optical depth − ln(spreading); x: μ_s, y: r
  // The table's grid coordinates (x, y) of (r, μ_s); none in the refracted shadow.
  std::optional<std::pair<double, double>> place(double r, double mu_sun) const;
};

}  // namespace skylit
