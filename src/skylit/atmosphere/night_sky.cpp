#include "skylit/atmosphere/night_sky.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"
#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/illuminants.h"

namespace skylit {

namespace {

// A spectrum scaled to a luminance (cd/m²); 0 stays 0.
Spectrum with_luminance(const Spectrum& shape, double cd_m2) {
  const double have = luminance(shape);
  return have > 0 && cd_m2 > 0 ? shape * static_cast<float>(cd_m2 / have) : Spectrum(0.0f);
}

// Airglow: a flat continuum (the pseudo-continuum of NO₂ and OH, Leinert et al. §9) with
// the 557.7 nm [O I] green line carrying a third of the visual luminance and the 630 nm
// red line a twentieth (their Fig. 38 and Table 18: about 250 and 100 rayleigh against
// a visual continuum near 1000 R). The lines go into the bin that holds them.
Spectrum airglow_shape(const SpectralBands& bands) {
  Spectrum continuum(1.0f), green(0.0f), red(0.0f);
  for (int i = 0; i < kSpectralBins; ++i) {
    const size_t b = static_cast<size_t>(i);
    const double lo = bands.lo_nm[b], hi = bands.hi_nm[b];
    if (557.7 >= lo && 557.7 < hi) green[i] = 1;
    if (630.0 >= lo && 630.0 < hi) red[i] = 1;
  }
  const double l_continuum = luminance(continuum);
  return continuum * static_cast<float>(1 / l_continuum) + with_luminance(green, 1.0 / 2) +
         with_luminance(red, 1.0 / 15);
}

Spectrum optical_depth(const Spectrum& transmittance) {
  Spectrum depth;
  for (int i = 0; i < kSpectralBins; ++i) depth[i] = -std::log(std::max(transmittance[i], 1e-30f));
  return depth;
}

}  // namespace

double van_rhijn_factor(double cos_zenith, double earth_radius_m, double layer_height_m) {
  const double ratio = earth_radius_m / (earth_radius_m + layer_height_m);
  const double sin2 = std::max(0.0, 1 - cos_zenith * cos_zenith);
  return 1 / std::sqrt(1 - ratio * ratio * sin2);
}

NightSky::NightSky(const NightSkySettings& settings, const SpectralBands& bands,
                   const TransmittanceTable& transmittance, double earth_radius_m)
    : settings_(settings), transmittance_(transmittance), earth_radius_m_(earth_radius_m) {
  const Spectrum sunlike = solar_extraterrestrial_irradiance();
  if (settings.natural) {
    airglow_ = with_luminance(airglow_shape(bands), settings.airglow_zenith_cd_m2);
    uniform_ = with_luminance(sunlike, settings.zodiacal_cd_m2 + settings.starlight_cd_m2);
  }
  Spectrum city = settings.artificial_spectrum;
  if (luminance(city) <= 0) city = Spectrum(1.0f);
  artificial_ = with_luminance(city, settings.artificial_zenith_cd_m2);
  zenith_depth_ = optical_depth(transmittance.to_top(transmittance.ground_radius(), 1.0));
  empty_ = luminance(airglow_) <= 0 && luminance(uniform_) <= 0 && luminance(artificial_) <= 0;
}

Spectrum NightSky::radiance_without_air(double cos_zenith) const {
  if (cos_zenith <= 0) return Spectrum(0.0f);
  return airglow_ * static_cast<float>(van_rhijn_factor(cos_zenith, earth_radius_m_, settings_.airglow_height_m)) +
         uniform_;
}

Spectrum NightSky::radiance(double cos_zenith) const {
  if (cos_zenith <= 0 || empty_) return Spectrum(0.0f);
  const Spectrum depth = optical_depth(transmittance_.to_top(transmittance_.ground_radius(), cos_zenith));
  const Spectrum natural = radiance_without_air(cos_zenith);
  Spectrum out;
  for (int i = 0; i < kSpectralBins; ++i) {
    // Relative to the zenith, where the settings' luminances hold; half the depth (above).
    const double natural_part = natural[i] * std::exp(-0.5 * (depth[i] - zenith_depth_[i]));
    const double tau = zenith_depth_[i];
    const double slab = tau > 1e-9 ? (1 - std::exp(-depth[i])) / (1 - std::exp(-tau)) : 1.0;
    out[i] = static_cast<float>(natural_part + artificial_[i] * slab);
  }
  return out;
}

Spectrum NightSky::horizontal_irradiance() const {
  // The midpoint rule in μ² (dμ² = 2μ dμ): smooth in it even where van Rhijn's factor
  // and the air mass rise steeply at the horizon.
  constexpr int kSteps = 512;
  Spectrum sum(0.0f);
  for (int k = 0; k < kSteps; ++k) sum += radiance(std::sqrt((k + 0.5) / kSteps));
  return sum * static_cast<float>(kPi / kSteps);
}

}  // namespace skylit
