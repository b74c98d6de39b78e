#include "skylit/atmosphere/multiple_scattering_table.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/phase_functions.h"
#include "skylit/atmosphere/shell_geometry.h"
#include "skylit/atmosphere/sun_zenith_rows.h"
#include "skylit/core/vec3.h"
#include "skylit/spectrum/spectral_math.h"

namespace skylit {

namespace {

// Directions spread evenly over the sphere (a spherical Fibonacci lattice): a fixed,
// deterministic quadrature with equal weights 4π/n.
Vec3 fibonacci_direction(int i, int n) {
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  const double z = 1.0 - (2.0 * i + 1.0) / n;
  const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {radius * std::cos(golden * i), radius * std::sin(golden * i), z};
}

// Table coordinates: altitude crowded toward the ground, where the density is; the sun's
// cosine crowded toward the horizon (sun_zenith_rows.h).
double altitude_from_unit(double x, double top) { return top * x * x; }
double unit_from_altitude(double h, double top) { return std::sqrt(std::clamp(h / top, 0.0, 1.0)); }

// Ψ_ms falls by orders of magnitude as the sun sets past the point's horizon, nearly
// exponentially: the table holds its logarithm, so that interpolating between rows
// follows the fall instead of overshooting it (linear interpolation of a convex
// curve), which made twilight skies too bright. Below the floor Ψ_ms is taken as 0.
constexpr float kPsiFloor = 1e-30f;
const float kLogPsiFloor = std::log(kPsiFloor) + 1.0f;

}  // namespace

MultipleScatteringTable::Factors MultipleScatteringTable::factors_at(const AtmosphereMedium& medium,
                                                                     const TransmittanceTable& transmittance,
                                                                     double ground_albedo, double r, double mu_sun,
                                                                     int directions, int segments) {
  const double rg = transmittance.ground_radius(), rt = transmittance.top_radius();
  const float isotropic = static_cast<float>(1.0 / kFourPi);
  const double sin_sun = std::sqrt(std::max(0.0, 1.0 - mu_sun * mu_sun));
  Spectrum second_order, transfer;
  for (int d = 0; d < directions; ++d) {
    // The sun lies in the x–z plane; ν is the cosine between view and sun.
    const Vec3 dir = fibonacci_direction(d, directions);
    const double mu = dir.z, nu = dir.x * sin_sun + dir.z * mu_sun;
    const bool ground = shell::hits_ground(r, mu, rg);
    const double length = ground ? shell::distance_to_ground(r, mu, rg) : shell::distance_to_outer_sphere(r, mu, rt);
    Spectrum throughput(1.0f), light, energy;
    // Segments crowded where the ray is lowest: 20 equal steps under-resolved the 1.2 km
    // aerosol layer (Ψ_ms off by −9 … +20 % below 500 m).
    const std::vector<double> bounds = shell::crowded_boundaries(length, -r * mu, segments);
    for (size_t s = 1; s < bounds.size(); ++s) {
      const double dt = bounds[s] - bounds[s - 1];
      const double t = 0.5 * (bounds[s] + bounds[s - 1]);
      const double r_t = shell::radius_at(r, mu, t);
      const double mu_s_t = std::clamp((r * mu_sun + t * nu) / r_t, -1.0, 1.0);
      const double h = r_t - medium.earth_radius_m;
      const double rho_r = medium.rayleigh_density(h), rho_a = medium.aerosol_density(h);
      const Spectrum extinction = medium.extinction(rho_r, rho_a, medium.ozone_density(h));
      const Spectrum scattering = medium.rayleigh_scattering * static_cast<float>(rho_r) +
                                  medium.aerosol_scattering * static_cast<float>(rho_a);
      const Spectrum segment_transmittance = transmittance_of(extinction * static_cast<float>(dt));
      const Spectrum sun = transmittance.sun(r_t, mu_s_t);
      for (int k = 0; k < kSpectralBins; ++k) {
        // ∫ over the segment of T·σ_s·(source) = T·σ_s·source·(1 − e^(−σ_t·dt))/σ_t.
        const float integral = segment_weight(extinction[k], static_cast<float>(dt), segment_transmittance[k]);
        light[k] += throughput[k] * scattering[k] * isotropic * sun[k] * integral;
        energy[k] += throughput[k] * scattering[k] * integral;
        throughput[k] *= segment_transmittance[k];
      }
    }
    if (ground) {
      // Light the sun puts on the ground, reflected (Lambert) toward the point.
      const double r_g = rg;
      const double mu_s_g = std::clamp((r * mu_sun + length * nu) / r_g, -1.0, 1.0);
      if (mu_s_g > 0) {
        const Spectrum sun = transmittance.sun(r_g, mu_s_g);
        for (int k = 0; k < kSpectralBins; ++k)
          light[k] += throughput[k] * sun[k] * static_cast<float>(mu_s_g * ground_albedo / kPi);
      }
      // The ground also returns multiply scattered light: a uniform radiance field
      // reflected by a Lambertian ground comes back scaled by its albedo (an extension
      // of Hillaire's f_ms, which counts the air only).
      for (int k = 0; k < kSpectralBins; ++k) energy[k] += throughput[k] * static_cast<float>(ground_albedo);
    }
    second_order += light;
    transfer += energy;
  }
  // Average over the sphere of directions, times 4π·(1/4π) for the isotropic phase.
  const float weight = 1.0f / static_cast<float>(directions);
  return {second_order * weight, transfer * weight};
}

MultipleScatteringTable::MultipleScatteringTable(const AtmosphereMedium& medium,
                                                 const TransmittanceTable& transmittance, double ground_albedo)
    : ground_radius_(transmittance.ground_radius()),
      top_radius_(transmittance.top_radius()),
      table_(kMuSunSize, kAltitudeSize) {
  tbb::parallel_for(0, kAltitudeSize, [&](int j) {
    const double r =
        ground_radius_ + altitude_from_unit(static_cast<double>(j) / (kAltitudeSize - 1), top_radius_ - ground_radius_);
    for (int i = 0; i < kMuSunSize; ++i) {
      const double mu_sun = mu_sun_from_unit(static_cast<double>(i) / (kMuSunSize - 1));
      const Factors f = factors_at(medium, transmittance, ground_albedo, r, mu_sun);
      Spectrum psi;
      for (int k = 0; k < kSpectralBins; ++k)
        psi[k] = std::log(std::max(f.second_order[k] / (1.0f - std::min(f.transfer[k], 0.999f)), kPsiFloor));
      table_.at(i, j) = psi;
    }
  });
}

Spectrum MultipleScatteringTable::psi(double r, double mu_sun) const {
  const double fi = unit_from_mu_sun(mu_sun) * (kMuSunSize - 1);
  const double fj = unit_from_altitude(r - ground_radius_, top_radius_ - ground_radius_) * (kAltitudeSize - 1);
  const Spectrum log_psi = table_.interpolate(fi, fj);
  Spectrum out;
  for (int k = 0; k < kSpectralBins; ++k) out[k] = log_psi[k] <= kLogPsiFloor ? 0.0f : std::exp(log_psi[k]);
  return out;
}

}  // namespace skylit
