// Light scattered toward the origin of a ray through the atmosphere (the paper's §3.1
// sky light; Bruneton & Neyret 2008 and Hillaire 2020 in today's form): along the ray,
// sunlight attenuated on its way to each point is scattered by molecules (Rayleigh) and
// aerosols (Mie) toward the origin, and attenuated again on the way there; multiple
// scattering adds σ_R·S_R + σ_A·S_A (scattering_orders_table.h) or, in Hillaire's
// approximation, σ_s·Ψ_ms (multiple_scattering_table.h); a ray that ends on the ground
// adds the ground's Lambertian reflection. Everything is per unit extraterrestrial
// solar irradiance: multiply by the sun's spectrum to get radiance.
#pragma once

#include <vector>

#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/multiple_scattering_table.h"
#include "skylit/atmosphere/transmittance_table.h"

namespace skylit {

class ScatteringOrdersTable;

struct ScatteredLight {
  Spectrum radiance;       // sr⁻¹, per unit solar irradiance
  Spectrum transmittance;  // from the origin to the end of the integrated part
};

// Sky irradiance on the ground (per unit solar irradiance) against the sun's zenith
// cosine, for the ground's reflection at the end of rays. It counts the sky as seen
// from the ground, without the ground's own reflection lighting the sky again.
class GroundIrradianceTable {
 public:
  static constexpr int kSize = 32;
  explicit GroundIrradianceTable(std::vector<Spectrum> irradiance) : irradiance_(std::move(irradiance)) {}
  Spectrum at(double mu_sun) const;

 private:
  std::vector<Spectrum> irradiance_;  // μ_s from −1 to 1
};

class ScatteringIntegrator {
 public:
  // `multiple`, `orders` and `ground_sky` may be null (the paper's model has none);
  // multiple scattering comes from `orders` (scattering_orders_table.h) or `multiple`
  // (Hillaire's approximation), whichever is given.
  ScatteringIntegrator(const AtmosphereMedium& medium, const TransmittanceTable& transmittance,
                       const MultipleScatteringTable* multiple, const GroundIrradianceTable* ground_sky,
                       const AerosolSettings& aerosol, double ground_albedo,
                       const ScatteringOrdersTable* orders = nullptr);

  // Along the ray (r, μ) to where it leaves the atmosphere or meets the ground, with the
  // sun at zenith cosine μ_s and ν = cos(angle between ray and sun). `segments` steps,
  // crowded where the ray is lowest.
  ScatteredLight along_ray(double r, double mu, double mu_sun, double nu, int segments) const;

  // The same, reporting the light gathered up to each of the increasing distances
  // `stops` (m), for aerial perspective: the ray goes on through the ground (as if the
  // air there were the ground's), so that directions just below the horizon, whose
  // rays would meet the Earth's curved surface kilometres away, still describe the air
  // in front of a surface of the scene's flat ground; a stop beyond the top of the
  // atmosphere gets the whole ray.
  std::vector<ScatteredLight> up_to(double r, double mu, double mu_sun, double nu,
                                    const std::vector<double>& stops) const;

  // The sun's single scattering alone that the stretch [t0, t1] of the ray (r, μ) sends
  // toward the ray's origin, dimmed by the air in front of it (per unit solar
  // irradiance; [0, t0] and [t0, t1] each in equal steps of at most `max_step_m`):
  // what the stretch's air stops adding when a building's shadow covers it. Rays
  // continue through the ground as in up_to.
  Spectrum sun_single_scattering(double r, double mu, double mu_sun, double nu, double t0, double t1,
                                 double max_step_m) const;

  // Irradiance from the sky on a horizontal plane at radius r (per unit solar
  // irradiance): ∫ L cos θ dω over the upper hemisphere by a midpoint rule in cos²θ and
  // azimuth (mirrored about the sun's vertical plane).
  Spectrum horizontal_irradiance(double r, double mu_sun, int zenith_steps, int azimuth_steps, int segments) const;

  // The sky irradiance table for the ground, built with this integrator.
  static GroundIrradianceTable ground_irradiance(const ScatteringIntegrator& sky_only);

  // Length of the ray (r, μ) inside the atmosphere, and whether it ends on the ground.
  double ray_length(double r, double mu, bool& ends_on_ground) const;

 private:
  struct Phases {
    float rayleigh, aerosol;
  };
  Phases phases(double nu) const;
  // The air at distance t along the ray (r, μ): its radius (rays continued through the
  // ground see the ground's air), densities and extinction.
  struct AirAt {
    double r;
    double rho_rayleigh, rho_aerosol;
    Spectrum extinction;
  };
  AirAt air_at(double r, double mu, double t) const;
  // Adds one segment [t0, t1] of the ray to `light`; without `multiple`, the sun's single
  // scattering alone.
  void add_segment(double r, double mu, double mu_sun, double nu, double t0, double t1, const Phases& phase,
                   ScatteredLight& light, bool multiple = true) const;
  void add_ground(double r, double mu_sun, double nu, double length, ScatteredLight& light) const;

  const AtmosphereMedium& medium_;
  const TransmittanceTable& transmittance_;
  const MultipleScatteringTable* multiple_;
  const ScatteringOrdersTable* orders_;
  const GroundIrradianceTable* ground_sky_;
  AerosolPhaseFunction aerosol_phase_;
  double ground_albedo_;
};

}  // namespace skylit
