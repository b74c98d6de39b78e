// One shadow volume's clip, and the lit pieces of a ray from its shadows (shadow_volume.h).
#include "skylit/geometry/shadow_volume.h"

#include <algorithm>
#include <cmath>

#include "skylit/geometry/shadow_casters.h"

namespace skylit {

namespace {

// Shadow or light shorter than this fraction of the scene's size is rounding, not
// geometry: where a ray passes through a vertex shared by several triangles, the
// neighbouring volumes' intervals are computed from different planes and can miss
// each other by a few ulps.
constexpr double kRelativeTolerance = 1e-9;

}  // namespace

void lit_intervals_from_shadows(const Ray& ray, double t_min, double t_max, double scale, bool no_volumes,
                                FunctionRef<void(const Vec3&, const Vec3&, std::vector<Interval>&)> collect_shadows,
                                std::vector<Interval>& out) {
  out.clear();
  if (std::isnan(t_min) || std::isnan(t_max) || t_min > t_max) return;
  const Vec3& o = ray.origin;
  const Vec3& dir = ray.direction;
  if (!is_finite(o) || !is_finite(dir) || no_volumes) {
    if (t_max > t_min) out.push_back({t_min, t_max});
    return;
  }
  const double dir_length = length(dir);
  const double tolerance = dir_length > 0 ? kRelativeTolerance * std::max(scale, max_abs(o)) / dir_length : 0;
  // Shadow: every volume's interval, collected in `out` and then turned into light.
  collect_shadows(o, dir, out);
  complement_of_union(t_min, t_max, tolerance, out);
}

}  // namespace skylit
