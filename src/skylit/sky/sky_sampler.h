// The sky as a light source for the path-traced reference: directions drawn in
// proportion to the sky's radiance (and the far ground's, below the horizon) as the
// scene's surfaces receive it (SkyModel::sky_radiance_near_ground), from a table of
// its mean radiance over a latitude–longitude grid of the whole sphere. The radiance
// itself is always read exactly from the sky model; the table only steers where
// directions go, so any table error costs noise, never bias.
#pragma once

#include <functional>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"

namespace skylit {

class SkySampler {
 public:
  // Rows in zenith angle θ over [0, π], columns in azimuth over [0, 2π).
  static constexpr int kRows = 64, kColumns = 128;

  using RadianceOf = std::function<Spectrum(const Vec3& direction)>;
  // For the sky's radiance as surfaces receive it, or any other radiance of direction.
  explicit SkySampler(const SkyModel& sky);
  explicit SkySampler(const RadianceOf& radiance);

  struct Sample {
    Vec3 direction;  // unit, world frame
    double pdf;      // sr⁻¹
  };
  // A direction from two uniform numbers in [0, 1).
  Sample sample(double u1, double u2) const;
  // The density of `direction` (unit), sr⁻¹.
  double pdf(const Vec3& direction) const;

 private:
  std::vector<double> cell_probability_;  // per cell, row by row
  std::vector<double> row_cdf_;           // kRows + 1 values
  std::vector<double> column_cdf_;        // per row, kColumns + 1 values
};

}  // namespace skylit
