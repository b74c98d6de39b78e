#include "skylit/atmosphere/solar_spectrum.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/seen_sun.h"

namespace skylit {

std::vector<SolarSpectrumSample> solar_spectrum(const AtmosphereSettings& settings, const Vec3& to_sun,
                                                double observer_height_m, int first_nm, int last_nm) {
  // kSpectralBins wavelengths at a time, the chunks in parallel; each writes its own rows.
  std::vector<SolarSpectrumSample> samples(static_cast<size_t>(std::max(0, last_nm - first_nm + 1)));
  const int chunks = (static_cast<int>(samples.size()) + kSpectralBins - 1) / kSpectralBins;
  tbb::parallel_for(0, chunks, [&](int c) {
    const int chunk = first_nm + c * kSpectralBins;
    const SpectralBands bands = SpectralBands::consecutive(chunk, 1.0);
    const Atmosphere atmosphere(settings, bands);
    // Directly from the integrator rather than through a sky model's tables: only
    // these three quantities are wanted, at many wavelengths.
    // `to_sun` is the sun as seen; the integrator's sun is the true one.
    const double sun_elevation =
        SunRefraction(atmosphere).true_elevation(std::asin(std::clamp(normalize(to_sun).z, -1.0, 1.0)));
    const double r = atmosphere.ground_radius() + observer_height_m, mu_sun = std::sin(sun_elevation);
    const Spectrum& e0 = atmosphere.extraterrestrial_irradiance().spectrum();
    const Spectrum direct = atmosphere.direct_sun_exact(observer_height_m, sun_elevation).spectrum();
    const Spectrum diffuse = atmosphere.integrator().horizontal_irradiance(r, mu_sun, 16, 16, 48) * e0;
    const Spectrum zenith = atmosphere.integrator().along_ray(r, 1.0, mu_sun, mu_sun, 96).radiance * e0;
    for (int i = 0; i < kSpectralBins && chunk + i <= last_nm; ++i)
      samples[static_cast<size_t>(chunk + i - first_nm)] = {static_cast<double>(chunk + i), direct[i], diffuse[i],
                                                            zenith[i]};
  });
  return samples;
}

}  // namespace skylit
