// Sky radiance seen from one observer for one sun, tabulated over view directions as
// in Hillaire (2020, §5.3): elevation crowded toward the horizon (where the sky changes
// fastest and meets the ground), azimuth measured from the sun's vertical plane (the
// sky is symmetric about it). Directions below the horizon see the ground through the
// air. Built once per scene; rendering only reads it.
#pragma once

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/scattering_integrator.h"
#include "skylit/core/function_ref.h"
#include "skylit/core/vec3.h"
#include "skylit/spectrum/spectrum_grid.h"

namespace skylit {

// A direction seen from an observer, relative to the sun.
struct RelativeDirection {
  double elevation_rad;         // above the local horizontal
  double azimuth_from_sun_rad;  // in [0, π], the angle between the horizontal projections
};

// Maps relative directions to table coordinates in [0, 1]² and back. u_elevation = ½
// is the horizon's dip angle at the observer's radius (the direction that grazes the
// ground); the sky lies above, the ground below.
class SkyDirectionMapping {
 public:
  SkyDirectionMapping(double observer_radius_m, double ground_radius_m);
  void to_unit(const RelativeDirection& d, double& u_azimuth, double& u_elevation) const;
  RelativeDirection from_unit(double u_azimuth, double u_elevation) const;

  // Calls f(i, j, cosines) for every node (i, j) of a size_x × size_y table over this
  // mapping (azimuth along x, elevation along y), rows in parallel.
  template <typename F>
  void for_each_node(int size_x, int size_y, double sun_elevation_rad, F&& f) const;
  double horizon_elevation_rad() const { return horizon_; }

 private:
  double horizon_;  // ≤ 0
};

RelativeDirection relative_direction(const Vec3& direction, const Vec3& to_sun);

// The cosines that the scattering integrals take for a direction: of its zenith angle
// (μ) and of its angle to the sun at elevation sun_elevation_rad (ν).
struct RayCosines {
  double mu, nu;
};
RayCosines ray_cosines(const RelativeDirection& direction, double sun_elevation_rad);

template <typename F>
void SkyDirectionMapping::for_each_node(int size_x, int size_y, double sun_elevation_rad, F&& f) const {
  tbb::parallel_for(0, size_y, [&](int j) {
    for (int i = 0; i < size_x; ++i)
      f(i, j,
        ray_cosines(from_unit(static_cast<double>(i) / (size_x - 1), static_cast<double>(j) / (size_y - 1)),
                    sun_elevation_rad));
  });
}

class SkyViewTable {
 public:
  static constexpr int kAzimuthSize = 96, kElevationSize = 128, kSegments = 32;

  // `sun_irradiance` scales the integrator's per-unit results into radiance.
  SkyViewTable(const ScatteringIntegrator& integrator, const Spectrum& sun_irradiance, double observer_radius_m,
               double ground_radius_m, double sun_elevation_rad);
  // Any other sky given as a function of the relative direction (a CIE sky), tabulated
  // over the same nodes.
  SkyViewTable(FunctionRef<Spectrum(const RelativeDirection&)> radiance, double observer_radius_m,
               double ground_radius_m);

  Spectrum radiance(const RelativeDirection& direction) const;
  const SkyDirectionMapping& mapping() const { return mapping_; }
  // Adds another light of the sky (the night sky's, night_sky.h) at every node.
  void add(FunctionRef<Spectrum(const RelativeDirection&)> radiance);

 private:
  SkyDirectionMapping mapping_;
  SpectrumGrid2D table_;
};

}  // namespace skylit
