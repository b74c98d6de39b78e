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

bool clip_to_volume(const ShadowVolume& volume, const Vec3& origin, const Vec3& direction, double& lo, double& hi) {
  for (int i = 0; i < 4; ++i) {
    const HalfSpace& f = volume.faces[i];
    const double a = dot(f.normal, origin) - f.offset;
    const double b = dot(f.normal, direction);
    if (b > 0) {
      lo = std::max(lo, -a / b);
    } else if (b < 0) {
      hi = std::min(hi, -a / b);
      if (!(lo < hi)) return false;
    } else if (a < 0 || (i == 3 && a == 0)) {
      return false;  // parallel to the face and outside (the cap open, the sides closed)
    }
  }
  return lo < hi;
}

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
