#include "skylit/atmosphere/aerial_perspective_table.h"

#include <algorithm>
#include <cmath>

#include "skylit/spectrum/spectral_math.h"

namespace skylit {

namespace {
// Distance of slice k: quadratic, so that near surfaces (tens of metres to a few km,
// most of a street scene) get most of the slices. Slice 0 is the observer itself.
double slice_distance(int k) {
  const double u = static_cast<double>(k) / (AerialPerspectiveTable::kDistanceSize - 1);
  return AerialPerspectiveTable::kMaxDistanceM * u * u;
}
}  // namespace

AerialPerspectiveTable::AerialPerspectiveTable(const ScatteringIntegrator& integrator, const Spectrum& sun_irradiance,
                                               double observer_radius_m, double ground_radius_m,
                                               double sun_elevation_rad)
    : mapping_(observer_radius_m, ground_radius_m),
      in_scattered_(kAzimuthSize, kElevationSize, kDistanceSize),
      optical_depth_(kAzimuthSize, kElevationSize, kDistanceSize) {
  std::vector<double> stops;
  for (int k = 1; k < kDistanceSize; ++k) stops.push_back(slice_distance(k));
  const double mu_sun = std::sin(sun_elevation_rad);
  mapping_.for_each_node(kAzimuthSize, kElevationSize, sun_elevation_rad, [&](int i, int j, const RayCosines& c) {
    const std::vector<ScatteredLight> light = integrator.up_to(observer_radius_m, c.mu, mu_sun, c.nu, stops);
    in_scattered_.at(i, j, 0) = Spectrum(0.0f);
    optical_depth_.at(i, j, 0) = Spectrum(0.0f);
    for (int k = 1; k < kDistanceSize; ++k) {
      const ScatteredLight& l = light[static_cast<size_t>(k - 1)];
      in_scattered_.at(i, j, k) = l.radiance * sun_irradiance;
      for (int b = 0; b < kSpectralBins; ++b)
        optical_depth_.at(i, j, k)[b] = -std::log(std::max(l.transmittance[b], 1e-30f));
    }
  });
}

AerialPerspectiveTable::Along AerialPerspectiveTable::along(const RelativeDirection& direction) const {
  double u_azimuth, u_elevation;
  mapping_.to_unit(direction, u_azimuth, u_elevation);
  return Along(*this, u_azimuth * (kAzimuthSize - 1), u_elevation * (kElevationSize - 1));
}

MediumStretch AerialPerspectiveTable::Along::at(double distance_m) const {
  // Linear in distance between the two slices around it: in-scatter and optical depth
  // grow in proportion to distance over short paths, so this is exact near the
  // observer (interpolating in the slices' own √d spacing is not).
  const double d = std::clamp(distance_m, 0.0, kMaxDistanceM);
  const int k = std::min(static_cast<int>(std::sqrt(d / kMaxDistanceM) * (kDistanceSize - 1)), kDistanceSize - 2);
  const double d0 = slice_distance(k), d1 = slice_distance(k + 1);
  const double fz = k + (d - d0) / (d1 - d0);
  return {Transmittance(transmittance_of(table_.optical_depth_.interpolate(fx_, fy_, fz))),
          Radiance(table_.in_scattered_.interpolate(fx_, fy_, fz))};
}

}  // namespace skylit
