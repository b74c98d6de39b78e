#include "skylit/atmosphere/refracted_ray.h"

#include "skylit/atmosphere/refracted_ray_impl.h"

namespace skylit {

RefractedRay trace_refracted_ray(const AtmosphereMedium& medium, double r, double mu_apparent, double ground_radius_m,
                                 double top_radius_m, int samples) {
  // The gradient by a central difference over ±1 m: the US Standard Atmosphere's
  // density is exponential within each 1 km row, so this is its slope but within 1 m
  // of a row's edge.
  constexpr double kStepM = 1.0;
  const auto air = [&medium](double h) {
    const double rho = medium.rayleigh_density(h);
    const double slope = (medium.rayleigh_density(h + kStepM) - medium.rayleigh_density(h - kStepM)) / (2 * kStepM);
    return refraction::AirSample{rho, medium.aerosol_density(h), medium.ozone_density(h),
                                 1.0 + medium.refractivity * rho, medium.refractivity * slope};
  };
  return refraction::trace(air, medium.earth_radius_m, r, mu_apparent, ground_radius_m, top_radius_m, samples);
}

}  // namespace skylit
