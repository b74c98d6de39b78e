// One cloud (cloud.h): the queries that choose between the sun grid and the march.
#include "skylit/clouds/cloud.h"

#include <cmath>
#include <limits>

namespace skylit {

double Cloud::transmittance(const Vec3& o, const Vec3& d, double t_min, double t_max) const {
  return std::exp(-optical_depth(o, d, t_min, t_max));
}

double Cloud::sun_transmittance(const Vec3& p, const Vec3& to_sun) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double t0, t1;
  if (!clip(p, to_sun, 0.0, kInf, t0, t1)) return 1.0;
  // With the sun prepared: the depth toward the sun from where the ray enters the
  // cloud's box is the whole depth along it (shadows on the ground, one look-up).
  if (sun_prepared_for(to_sun)) return std::exp(-interpolated_sun_depth(p + to_sun * t0));
  return std::exp(-optical_depth(p, to_sun, 0.0, kInf));
}

Spectrum Cloud::radiance(const Vec3& o, const Vec3& d, double t_min, double t_max, const Spectrum& behind,
                         const CloudLighting& light) const {
  const CloudScattering s = scatter(o, d, t_min, t_max, light);
  return behind * static_cast<float>(s.transmittance) + s.in_scattered;
}

}  // namespace skylit
