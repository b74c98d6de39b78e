#include "skylit/atmosphere/scattering_integrator.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/phase_functions.h"
#include "skylit/atmosphere/scattering_orders_table.h"
#include "skylit/atmosphere/shell_geometry.h"
#include "skylit/core/vec3.h"
#include "skylit/spectrum/spectral_math.h"

namespace skylit {

Spectrum GroundIrradianceTable::at(double mu_sun) const {
  const double f = (std::clamp(mu_sun, -1.0, 1.0) + 1.0) * 0.5 * (kSize - 1);
  const int i = std::min(static_cast<int>(f), kSize - 2);
  const float a = static_cast<float>(f - i);
  return irradiance_[static_cast<size_t>(i)] * (1 - a) + irradiance_[static_cast<size_t>(i + 1)] * a;
}

ScatteringIntegrator::ScatteringIntegrator(const AtmosphereMedium& medium, const TransmittanceTable& transmittance,
                                           const MultipleScatteringTable* multiple,
                                           const GroundIrradianceTable* ground_sky, const AerosolSettings& aerosol,
                                           double ground_albedo, const ScatteringOrdersTable* orders)
    : medium_(medium),
      transmittance_(transmittance),
      multiple_(multiple),
      orders_(orders),
      ground_sky_(ground_sky),
      aerosol_phase_(aerosol),
      ground_albedo_(ground_albedo) {}

ScatteringIntegrator::Phases ScatteringIntegrator::phases(double nu) const {
  return {static_cast<float>(rayleigh_phase(nu, medium_.rayleigh_gamma)), static_cast<float>(aerosol_phase_(nu))};
}

double ScatteringIntegrator::ray_length(double r, double mu, bool& ends_on_ground) const {
  ends_on_ground = shell::hits_ground(r, mu, transmittance_.ground_radius());
  return ends_on_ground ? shell::distance_to_ground(r, mu, transmittance_.ground_radius())
                        : shell::distance_to_outer_sphere(r, mu, transmittance_.top_radius());
}

ScatteringIntegrator::AirAt ScatteringIntegrator::air_at(double r, double mu, double t) const {
  const double r_t = std::max(shell::radius_at(r, mu, t), transmittance_.ground_radius());
  const double h = r_t - medium_.earth_radius_m;
  const double rho_r = medium_.rayleigh_density(h), rho_a = medium_.aerosol_density(h);
  return {r_t, rho_r, rho_a, medium_.extinction(rho_r, rho_a, medium_.ozone_density(h))};
}

void ScatteringIntegrator::add_segment(double r, double mu, double mu_sun, double nu, double t0, double t1,
                                       const Phases& phase, ScatteredLight& light, bool multiple) const {
  const double dt = t1 - t0;
  if (dt <= 0) return;
  // Sources at the segment's midpoint; the attenuation across it is integrated exactly.
  const double t = 0.5 * (t0 + t1);
  // Rays continued through the ground (aerial perspective) see the ground's air there.
  const AirAt air = air_at(r, mu, t);
  const double r_t = air.r, rho_r = air.rho_rayleigh, rho_a = air.rho_aerosol;
  const Spectrum& extinction = air.extinction;
  const double mu_sun_t = std::clamp((r * mu_sun + t * nu) / r_t, -1.0, 1.0);
  const Spectrum segment = transmittance_of(extinction * static_cast<float>(dt));
  const Spectrum sun = transmittance_.sun(r_t, mu_sun_t);
  // Multiply scattered light per unit σ_R and σ_A (equal for Hillaire's isotropic Ψ_ms).
  ScatteringOrdersTable::Source ms{Spectrum(0.0f), Spectrum(0.0f)};
  if (multiple && orders_) {
    ms = orders_->at(r_t, shell::mu_at(r, mu, t, r_t), mu_sun_t, nu);
  } else if (multiple && multiple_) {
    ms.rayleigh = multiple_->psi(r_t, mu_sun_t);
    ms.aerosol = ms.rayleigh;
  }
  const float fr = static_cast<float>(rho_r), fa = static_cast<float>(rho_a), fdt = static_cast<float>(dt);
  for (int k = 0; k < kSpectralBins; ++k) {
    const float sigma_r = medium_.rayleigh_scattering[k] * fr, sigma_a = medium_.aerosol_scattering[k] * fa;
    const float source = (sigma_r * phase.rayleigh + sigma_a * phase.aerosol) * sun[k] + sigma_r * ms.rayleigh[k] +
                         sigma_a * ms.aerosol[k];
    const float integral = segment_weight(extinction[k], fdt, segment[k]);
    light.radiance[k] += light.transmittance[k] * source * integral;
    light.transmittance[k] *= segment[k];
  }
}

Spectrum ScatteringIntegrator::sun_single_scattering(double r, double mu, double mu_sun, double nu, double t0,
                                                     double t1, double max_step_m) const {
  if (!(t1 > t0) || !(max_step_m > 0)) return Spectrum(0.0f);
  const auto steps = [max_step_m](double length) {
    return static_cast<int>(std::clamp(std::ceil(length / max_step_m), 1.0, 1e4));
  };
  // The air in front only dims; the stretch gathers the sun's single scattering, as
  // add_segment does without the multiple scattering.
  ScatteredLight light{Spectrum(0.0f), Spectrum(1.0f)};
  const double front = std::max(t0, 0.0);
  const int n_front = steps(front), n_stretch = steps(t1 - front);
  for (int k = 0; k < n_front && front > 0; ++k) {
    const double dt = front / n_front, t = (k + 0.5) * dt;
    light.transmittance *= transmittance_of(air_at(r, mu, t).extinction * static_cast<float>(dt));
  }
  const Phases phase = phases(nu);
  for (int k = 0; k < n_stretch; ++k)
    add_segment(r, mu, mu_sun, nu, front + (t1 - front) * k / n_stretch, front + (t1 - front) * (k + 1) / n_stretch,
                phase, light, false);
  return light.radiance;
}

void ScatteringIntegrator::add_ground(double r, double mu_sun, double nu, double length, ScatteredLight& light) const {
  const double rg = transmittance_.ground_radius();
  const double mu_sun_g = std::clamp((r * mu_sun + length * nu) / rg, -1.0, 1.0);
  Spectrum irradiance = mu_sun_g > 0 ? transmittance_.sun(rg, mu_sun_g) * static_cast<float>(mu_sun_g) : Spectrum(0.0f);
  if (ground_sky_) irradiance += ground_sky_->at(mu_sun_g);
  for (int k = 0; k < kSpectralBins; ++k)
    light.radiance[k] += light.transmittance[k] * irradiance[k] * static_cast<float>(ground_albedo_ / kPi);
}

ScatteredLight ScatteringIntegrator::along_ray(double r, double mu, double mu_sun, double nu, int segments) const {
  bool ground = false;
  const double length = ray_length(r, mu, ground);
  const Phases phase = phases(nu);
  ScatteredLight light{Spectrum(0.0f), Spectrum(1.0f)};
  const std::vector<double> t = shell::crowded_boundaries(length, -r * mu, segments);
  for (size_t k = 1; k < t.size(); ++k) add_segment(r, mu, mu_sun, nu, t[k - 1], t[k], phase, light);
  if (ground) add_ground(r, mu_sun, nu, length, light);
  return light;
}

std::vector<ScatteredLight> ScatteringIntegrator::up_to(double r, double mu, double mu_sun, double nu,
                                                        const std::vector<double>& stops) const {
  const double length = shell::distance_to_outer_sphere(r, mu, transmittance_.top_radius());
  const Phases phase = phases(nu);
  ScatteredLight light{Spectrum(0.0f), Spectrum(1.0f)};
  std::vector<ScatteredLight> out;
  out.reserve(stops.size());
  double t_prev = 0.0;
  for (double stop : stops) {
    const double t = std::min(stop, length);
    // Two segments per interval between stops keep the midpoint rule accurate where
    // the stops are far apart.
    const double mid = 0.5 * (t_prev + t);
    add_segment(r, mu, mu_sun, nu, t_prev, mid, phase, light);
    add_segment(r, mu, mu_sun, nu, mid, t, phase, light);
    t_prev = t;
    out.push_back(light);
  }
  return out;
}

Spectrum ScatteringIntegrator::horizontal_irradiance(double r, double mu_sun, int zenith_steps, int azimuth_steps,
                                                     int segments) const {
  // With v = cos²θ, cos θ sin θ dθ = ½ dv: equal steps in v carry equal weights of the
  // cosine law; each sample stands for π/(zenith_steps · azimuth_steps) of the π total.
  const double sin_sun = std::sqrt(std::max(0.0, 1.0 - mu_sun * mu_sun));
  Spectrum sum;
  for (int z = 0; z < zenith_steps; ++z) {
    const double mu = std::sqrt((z + 0.5) / zenith_steps);
    const double sin_view = std::sqrt(1.0 - mu * mu);
    for (int a = 0; a < azimuth_steps; ++a) {
      const double phi = kPi * (a + 0.5) / azimuth_steps;
      const double nu = mu * mu_sun + sin_view * sin_sun * std::cos(phi);
      sum += along_ray(r, mu, mu_sun, nu, segments).radiance;
    }
  }
  return sum * static_cast<float>(kPi / (zenith_steps * azimuth_steps));
}

GroundIrradianceTable ScatteringIntegrator::ground_irradiance(const ScatteringIntegrator& sky) {
  constexpr int kZenith = 8, kAzimuth = 8, kSegments = 24;
  const double r = sky.transmittance_.ground_radius();
  std::vector<Spectrum> table(static_cast<size_t>(GroundIrradianceTable::kSize));
  tbb::parallel_for(0, GroundIrradianceTable::kSize, [&](int i) {
    const double mu_sun = -1.0 + 2.0 * i / (GroundIrradianceTable::kSize - 1);
    table[static_cast<size_t>(i)] = sky.horizontal_irradiance(r, mu_sun, kZenith, kAzimuth, kSegments);
  });
  return GroundIrradianceTable(std::move(table));
}

}  // namespace skylit
