// The natural night sky (airglow, zodiacal light, integrated starlight) and a city's
// artificial sky glow, as radiance over the sky's zenith angle. Tiny beside any lamp or
// the sun, but what sets an unlit scene's level on a moonless night. The sky model adds
// it to its sky-view tables (atmosphere.cpp), so it is seen in the sky and lights
// surfaces through the same sky irradiance as the scattered sunlight. docs/night-sky.md.
#pragma once

#include "skylit/atmosphere/night_sky_settings.h"
#include "skylit/atmosphere/transmittance_table.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// Van Rhijn's factor: how much longer the line of sight through a thin emitting layer at
// height h is than the vertical, 1/√(1 − (R/(R+h))² sin² z).
double van_rhijn_factor(double cos_zenith, double earth_radius_m, double layer_height_m);

// The night sky's radiance above the horizon, seen from the ground.
//   natural: each source's zenith luminance × its angular law (van Rhijn for the
//     airglow, uniform for zodiacal light and starlight) × the air's transmittance
//     toward that direction relative to the zenith, taken at half the optical depth:
//     the night sky is nearly uniform, so about half of what the air scatters out of a
//     line of sight is scattered back into it from the rest of the sky (the dark ground
//     gives nothing); a documented approximation, not a radiative transfer solution.
//   artificial: the glowing air as a uniform slab lit from below, L ∝ 1 − e^{−τX}:
//     L(z) = L_zen (1 − e^{−τ X(z)})/(1 − e^{−τ}), τ the air's vertical optical depth
//     and X(z) its relative air mass, both at each wavelength from the transmittance
//     table. It rises toward the horizon (to 1/(1 − e^{−τ}) at X → ∞: about 4× for
//     τ = 0.3), as measured skies near cities do (Kocifaj, JQSRT 2007; Duriscoe 2016).
class NightSky {
 public:
  NightSky(const NightSkySettings& settings, const SpectralBands& bands, const TransmittanceTable& transmittance,
           double earth_radius_m);
  // W m⁻² sr⁻¹ nm⁻¹ at zenith cosine μ > 0 (0 at and below the horizon).
  Spectrum radiance(double cos_zenith) const;
  // The same without the air (no extinction, no artificial slab law): the sources'
  // angular laws alone, for tests of van Rhijn's factor.
  Spectrum radiance_without_air(double cos_zenith) const;
  // Its irradiance on a horizontal plane, W m⁻² nm⁻¹: 2π ∫ L(μ) μ dμ (the midpoint rule in μ²).
  Spectrum horizontal_irradiance() const;
  bool empty() const { return empty_; }

 private:
  NightSkySettings settings_;
  const TransmittanceTable& transmittance_;
  double earth_radius_m_;
  Spectrum airglow_, uniform_, artificial_;  // zenith radiance spectra
  Spectrum zenith_depth_;                    // the air's vertical optical depth
  bool empty_ = true;
};

}  // namespace skylit
