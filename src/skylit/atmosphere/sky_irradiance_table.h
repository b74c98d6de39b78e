// Irradiance from the whole sky and the ground around on a small plane of any
// orientation, with nothing in the way: ∫ L(ω) max(0, n·ω) dω over the sphere, L from a
// sky-view table (so the lower half is the ground seen through the air). Tabulated over
// the plane's normal: its elevation and its azimuth from the sun.
#pragma once

#include <vector>

#include "skylit/atmosphere/sky_view_table.h"

namespace skylit {

class SkyIrradianceTable {
 public:
  static constexpr int kNormalAzimuthSize = 17, kNormalElevationSize = 17;

  SkyIrradianceTable(const SkyViewTable& sky, const Vec3& to_sun);

  // W m⁻² nm⁻¹ on a plane with unit normal `normal` (world frame).
  Spectrum at(const Vec3& normal) const;

  // The integral itself, for any normal, by the table's quadrature (for tests and for
  // the diffuse horizontal irradiance).
  static Spectrum integrate(const SkyViewTable& sky, const RelativeDirection& normal);

  // The sphere of directions sampled once: directions (sun's azimuth along +x) and the
  // sky's radiance there, each standing for the same solid angle.
  struct SampledSphere {
    std::vector<Vec3> directions;
    std::vector<Spectrum> radiance;
    float solid_angle_each;
  };
  static SampledSphere sample(const SkyViewTable& sky);
  static Spectrum integrate(const SampledSphere& sphere, const Vec3& normal);

 private:
  Vec3 to_sun_;
  SpectrumGrid2D table_;
};

}  // namespace skylit
