#include "skylit/atmosphere/sun_disc.h"

#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

double limb_darkening_exponent(double wavelength_nm) { return -0.023 + 0.292 / (wavelength_nm * 1e-3); }

Spectrum sun_disc_radiance(const Spectrum& irradiance, const SpectralBands& bands, double angular_radius_rad,
                           double angle_from_centre_rad) {
  if (angle_from_centre_rad >= angular_radius_rad) return Spectrum(0.0f);
  const double solid_angle = 2.0 * kPi * (1.0 - std::cos(angular_radius_rad));
  const double s = angle_from_centre_rad / angular_radius_rad;
  const double mu = std::sqrt(1.0 - s * s);
  Spectrum out;
  for (int i = 0; i < kSpectralBins; ++i) {
    // The mean of μ^α over the disc is 2/(α + 2): the centre is brighter by (α + 2)/2.
    const double alpha = limb_darkening_exponent(bands.center_nm(i));
    out[i] = static_cast<float>(irradiance[i] / solid_angle * (alpha + 2.0) / 2.0 * std::pow(mu, alpha));
  }
  return out;
}

}  // namespace skylit
