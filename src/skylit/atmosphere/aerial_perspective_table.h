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
  MediumStretch at(const RelativeDirection& direction, double distance_m) const {
    return along(direction).at(distance_m);
  }

  // The table along one direction, its place in the table found once: a view ray in fog
  // asks for two or three distances (to the fog, to where the fog hides the rest, to
  // the surface), and finding the direction's place cost as much as a look-up.
  class Along {
   public:
    MediumStretch at(double distance_m) const;

   private:
    friend class AerialPerspectiveTable;
    Along(const AerialPerspectiveTable& table, double fx, double fy) : table_(table), fx_(fx), fy_(fy) {}
    const AerialPerspectiveTable& table_;
    double fx_, fy_;  // fractional azimuth and elevation indices
  };
  Along along(const RelativeDirection& direction) const;

 private:
  SkyDirectionMapping mapping_;
  SpectrumGrid3D in_scattered_;
  SpectrumGrid3D optical_depth_;  // −ln T: interpolates far better than T at long range
};

}  // namespace skylit
