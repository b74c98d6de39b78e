// Aerial perspective: the light the air between the observer and a surface adds
// (in-scattered radiance) and the fraction of the surface's light that gets through
// (transmittance), over view directions and distances from one observer. The same
// integral as the sky's (scattering_integrator.h), stopped at the surface.
#pragma once

#include <vector>

#include "skylit/atmosphere/sky_view_table.h"
#include "skylit/spectrum/medium_stretch.h"

namespace skylit {

class AerialPerspectiveTable {
 public:
  // An odd number of elevation rows puts one exactly at the horizon's dip.
  static constexpr int kAzimuthSize = 32, kElevationSize = 33, kDistanceSize = 33;
  static constexpr double kMaxDistanceM = 80e3;  // farther surfaces use this distance's values

  AerialPerspectiveTable(const ScatteringIntegrator& integrator, const Spectrum& sun_irradiance,
                         double observer_radius_m, double ground_radius_m, double sun_elevation_rad);

  // In-scattered radiance (W m⁻² sr⁻¹ nm⁻¹) and transmittance over `distance_m` along `direction`.
  MediumStretch at(const RelativeDirection& direction, double distance_m) const;

 private:
  SkyDirectionMapping mapping_;
  SpectrumGrid3D in_scattered_;
  SpectrumGrid3D optical_depth_;  // −ln T: interpolates far better than T at long range
};

}  // namespace skylit
