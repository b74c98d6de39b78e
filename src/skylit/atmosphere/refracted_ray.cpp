#include "skylit/atmosphere/refracted_ray.h"

#include "skylit/atmosphere/refracted_ray_impl.h"

namespace skylit {

namespace refraction {

AirSample air_sample(const AtmosphereMedium& medium, double h) {
  constexpr double kStepM = 1.0;
  const double rho = medium.rayleigh_density(h);
  const double slope = (medium.rayleigh_density(h + kStepM) - medium.rayleigh_density(h - kStepM)) / (2 * kStepM);
  return {rho, medium.aerosol_density(h), medium.ozone_density(h), 1.0 + medium.refractivity * rho,
          medium.refractivity * slope};
}

}  // namespace refraction

RefractedRay trace_refracted_ray(const AtmosphereMedium& medium, double r, double mu_apparent, double ground_radius_m,
                                 double top_radius_m, int samples) {
  const auto air = [&medium](double h) { return refraction::air_sample(medium, h); };
  return refraction::trace(air, medium.earth_radius_m, r, mu_apparent, ground_radius_m, top_radius_m, samples);
}

}  // namespace skylit
