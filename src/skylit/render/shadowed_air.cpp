#include "skylit/render/shadowed_air.h"

#include <algorithm>
#include <cmath>

namespace skylit {

ShadowedAir::ShadowedAir(const std::vector<const TriangleMesh*>& meshes, const SkyModel& sky)
    : sky_(sky), shadows_(meshes, sky.to_sun()) {}

Radiance ShadowedAir::hidden_sunlight(const Ray& ray, double distance_m) const {
  Radiance hidden(0.0f);
  if (!(distance_m > 0) || !std::isfinite(distance_m)) return hidden;
  thread_local std::vector<Interval> sunlit;
  shadows_.sunlit_intervals(ray, 0.0, distance_m, sunlit);
  // The shadowed parts are the gaps between the sunlit ones (sorted, disjoint).
  double from = 0.0;
  for (const Interval& lit : sunlit) {
    if (lit.begin > from) hidden += sky_.sunlit_air(ray.direction, from, lit.begin);
    from = std::max(from, lit.end);
  }
  if (distance_m > from) hidden += sky_.sunlit_air(ray.direction, from, distance_m);
  return hidden;
}

MediumStretch ShadowedAir::in_shadows(const MediumStretch& air, const Ray& ray, double distance_m) const {
  const Radiance hidden = hidden_sunlight(ray, distance_m);
  MediumStretch out = air;
  // Never below nothing: the table and the steps here are separate quadratures.
  Spectrum light = air.in_scattered.spectrum();
  for (int k = 0; k < kSpectralBins; ++k) light[k] = std::max(0.0f, light[k] - hidden[k]);
  out.in_scattered = Radiance(light);
  return out;
}

}  // namespace skylit
