#include "skylit/atmosphere/cie_sky_view.h"

#include <algorithm>
#include <cmath>

#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/illuminants.h"

namespace skylit {

Spectrum d65_per_candela(const SpectralBands& bands) {
  const Tabulated& d65 = cie_d65_table();
  const double luminance_of_table = luminance(Spectrum::from_table(d65));
  Spectrum s;
  for (int i = 0; i < kSpectralBins; ++i)
    s[i] = static_cast<float>(d65.average(bands.lo_nm[static_cast<size_t>(i)], bands.hi_nm[static_cast<size_t>(i)]) /
                              luminance_of_table);
  return s;
}

double cie_zenith_luminance(const CieSkySettings& settings, const Vec3& to_sun) {
  return settings.diffuse_horizontal_lux /
         cie_horizontal_illuminance_per_zenith_luminance(cie_sky_parameters(settings.type), to_sun);
}

std::unique_ptr<SkyViewTable> cie_sky_view(const CieSkySettings& settings, const SpectralBands& bands,
                                           const Vec3& to_sun, const Irradiance& sun_on_ground, double ground_albedo,
                                           double observer_radius_m, double ground_radius_m) {
  const CieSkyParameters p = cie_sky_parameters(settings.type);
  const Spectrum per_candela = d65_per_candela(bands);
  const double zenith = cie_zenith_luminance(settings, to_sun);
  const Spectrum ground =
      (per_candela * static_cast<float>(settings.diffuse_horizontal_lux) + sun_on_ground.spectrum()) *
      static_cast<float>(ground_albedo / kPi);
  // The table's directions are relative to the sun's vertical: the sun at azimuth 0.
  const double sun_horizontal = std::hypot(to_sun.x, to_sun.y);
  const Vec3 sun_in_table{sun_horizontal, 0.0, to_sun.z};
  return std::make_unique<SkyViewTable>(
      [&](const RelativeDirection& d) {
        if (d.elevation_rad < 0) return ground;
        const Vec3 view{std::cos(d.elevation_rad) * std::cos(d.azimuth_from_sun_rad),
                        std::cos(d.elevation_rad) * std::sin(d.azimuth_from_sun_rad), std::sin(d.elevation_rad)};
        return per_candela * static_cast<float>(zenith * cie_relative_luminance(p, view, sun_in_table));
      },
      observer_radius_m, ground_radius_m);
}

}  // namespace skylit
