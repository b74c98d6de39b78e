#include "skylit/atmosphere/transmittance_table.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/refracted_sun_table.h"
#include "skylit/atmosphere/shell_geometry.h"
#include "skylit/spectrum/spectral_math.h"

namespace skylit {

namespace {

// Simpson's rule for ∫ f(t) dt between `from` and `to` (either order) after the
// substitution t = from + (to − from)·u², u ∈ [0, 1], which crowds samples at `from`.
template <typename AddSample>
void integrate_crowded_at(double from, double to, int intervals, AddSample&& add_sample) {
  const int m = std::max(2, intervals + intervals % 2);  // Simpson wants an even count
  const double span = to - from, h = 1.0 / m;
  for (int k = 0; k <= m; ++k) {
    const double u = k * h;
    const double weight = (k == 0 || k == m) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    add_sample(from + span * u * u, weight * h / 3.0 * 2.0 * u * std::abs(span));
  }
}

// ∫ over [0, length] with samples crowded where the ray passes its lowest altitude
// t_low (0 for rays going up), where the densities peak.
template <typename AddSample>
void integrate_along_ray(double length, double t_low, int intervals, AddSample&& add_sample) {
  if (t_low <= 0.0 || t_low >= length) {
    integrate_crowded_at(0.0, length, intervals, add_sample);
    return;
  }
  const int before = std::max(2, static_cast<int>(intervals * t_low / length));
  integrate_crowded_at(t_low, 0.0, before, add_sample);
  integrate_crowded_at(t_low, length, std::max(2, intervals - before), add_sample);
}

}  // namespace

ColumnDensities column_densities(const AtmosphereMedium& medium, double r, double mu, double length, int samples) {
  ColumnDensities sum;
  const double t_low = -r * mu;  // where the ray is closest to the Earth's centre
  integrate_along_ray(length, t_low, samples, [&](double t, double weight) {
    const double altitude = shell::radius_at(r, mu, t) - medium.earth_radius_m;
    sum.rayleigh += weight * medium.rayleigh_density(altitude);
    sum.aerosol += weight * medium.aerosol_density(altitude);
    sum.ozone += weight * medium.ozone_density(altitude);
  });
  return sum;
}

namespace {

// Bruneton's mapping between (r, μ) and table coordinates in [0, 1]², for rays that
// do not meet the ground: x_μ spans the distance to the top between its least (d_min,
// straight up) and greatest (d_max, grazing the ground) values at this r.
struct TransmittanceMapping {
  double rg, rt, h;  // ground, top radius; H = √(rt² − rg²)

  void to_unit(double r, double mu, double& x_mu, double& x_r) const {
    const double rho = std::sqrt(std::max(0.0, r * r - rg * rg));
    const double d = shell::distance_to_outer_sphere(r, mu, rt);
    const double d_min = rt - r, d_max = rho + h;
    x_mu = d_max > d_min ? (d - d_min) / (d_max - d_min) : 0.0;
    x_r = rho / h;
  }
  void from_unit(double x_mu, double x_r, double& r, double& mu) const {
    const double rho = h * x_r;
    r = std::sqrt(rho * rho + rg * rg);
    const double d_min = rt - r, d_max = rho + h;
    const double d = d_min + x_mu * (d_max - d_min);
    mu = d == 0.0 ? 1.0 : std::clamp((h * h - rho * rho - d * d) / (2.0 * r * d), -1.0, 1.0);
  }
};

}  // namespace

TransmittanceTable::TransmittanceTable(const AtmosphereMedium& medium, double ground_radius_m, double top_radius_m)
    : ground_radius_(ground_radius_m),
      top_radius_(top_radius_m),
      horizon_distance_(std::sqrt(top_radius_m * top_radius_m - ground_radius_m * ground_radius_m)),
      table_(kMuSize, kRSize) {
  const TransmittanceMapping map{ground_radius_, top_radius_, horizon_distance_};
  tbb::parallel_for(0, kRSize, [&](int j) {
    for (int i = 0; i < kMuSize; ++i) {
      double r, mu;
      map.from_unit(static_cast<double>(i) / (kMuSize - 1), static_cast<double>(j) / (kRSize - 1), r, mu);
      const ColumnDensities c = column_densities(medium, r, mu, shell::distance_to_outer_sphere(r, mu, top_radius_));
      table_.at(i, j) = medium.extinction(c.rayleigh, c.aerosol, c.ozone);
    }
  });
  if (medium.refractivity > 0) refracted_ = std::make_shared<RefractedSunTable>(medium, ground_radius_m, top_radius_m);
}

Spectrum TransmittanceTable::sun(double r, double mu_sun) const {
  return refracted_ ? refracted_->sunlight(r, mu_sun) : to_top(r, mu_sun);
}

void TransmittanceTable::sun_in_bins(double r, double mu_sun, std::span<const int> bins, std::span<float> out) const {
  if (refracted_) return refracted_->sunlight_in_bins(r, mu_sun, bins, out);
  transmittance_in_bins(table_, place(r, mu_sun), bins, out);
}

std::optional<std::pair<double, double>> TransmittanceTable::place(double r, double mu) const {
  r = std::clamp(r, ground_radius_, top_radius_);
  if (shell::hits_ground(r, mu, ground_radius_)) return std::nullopt;
  const TransmittanceMapping map{ground_radius_, top_radius_, horizon_distance_};
  double x_mu, x_r;
  map.to_unit(r, mu, x_mu, x_r);
  return std::pair{x_mu * (kMuSize - 1), x_r * (kRSize - 1)};
}

Spectrum TransmittanceTable::to_top(double r, double mu) const {
  const auto at = place(r, mu);
  return at ? transmittance_of(table_.interpolate(at->first, at->second)) : Spectrum(0.0f);
}

}  // namespace skylit
