// One shadow volume (Crow 1977, "Shadow algorithms for computer graphics", SIGGRAPH '77,
// Comput Graph 11(2):242-247) and what both light kinds do with many of them. A casting
// triangle's volume is convex: the intersection of four half-spaces, three sides
// through its edges (parallel to the sun's direction for the sun, through the light for
// a point light) and the triangle's own plane (the cap). A ray meets it in one interval,
// found by clipping; a ray's light is the complement of the union of those intervals.
// Crow counts the volume faces a ray crosses; clipping each volume on its own and
// uniting the intervals needs no count at the ray's origin (a camera standing in
// shade) and gives the same set. docs/geometry.md, "Shadow volumes".
#pragma once

#include <algorithm>

#include <array>
#include <cstddef>
#include <vector>

#include "skylit/core/function_ref.h"
#include "skylit/core/vec3.h"
#include "skylit/geometry/intervals.h"
#include "skylit/geometry/ray_tracer.h"

namespace skylit {

// Bounding boxes and spheres around volumes are padded by this fraction of the scene's
// size, so that a bound test rounded the other way can never drop a volume that the
// exact clip would keep.
inline constexpr double kRelativeShadowBoundPadding = 1e-8;

// Inside: dot(normal, x) >= offset.
struct HalfSpace {
  Vec3 normal;
  double offset;
};

// Three sides through the casting triangle's edges, then its own plane (the cap).
struct ShadowVolume {
  std::array<HalfSpace, 4> faces;
};

// Clips origin + t direction, t in [lo, hi], to the convex volume inside planes[0..count),
// the last its cap; true if something is left. The sides are closed, so a ray lying in
// a side shared by two volumes is in both; the cap is open, so a ray running along a
// lit surface (a view ray grazing the ground) stays lit.
// Inline: it runs once per volume per query, the innermost loop of beams and lamp glow.
inline bool clip_to_half_spaces(const HalfSpace* planes, size_t count, const Vec3& origin, const Vec3& direction,
                                double& lo, double& hi) {
  for (size_t i = 0; i < count; ++i) {
    const HalfSpace& f = planes[i];
    const double a = dot(f.normal, origin) - f.offset;
    const double b = dot(f.normal, direction);
    if (b > 0) {
      lo = std::max(lo, -a / b);
    } else if (b < 0) {
      hi = std::min(hi, -a / b);
      if (!(lo < hi)) return false;
    } else if (a < 0 || (i + 1 == count && a == 0)) {
      return false;  // parallel to the plane and outside (the cap open, the sides closed)
    }
  }
  return lo < hi;
}

// The same for a prism or a triangle's frustum.
inline bool clip_to_volume(const ShadowVolume& volume, const Vec3& origin, const Vec3& direction, double& lo,
                           double& hi) {
  return clip_to_half_spaces(volume.faces.data(), volume.faces.size(), origin, direction, lo, hi);
}

// The lit parts of ray.origin + t ray.direction, t in [t_min, t_max], into `out`
// (cleared first): collect_shadows(o, d, out) appends the shadow intervals of the volumes
// the ray may meet, and their union's complement is lit. `scale` is the size of the scene
// (the largest coordinate of the casters and the light, at least 1 m); light or shadow
// shorter than 1e-9 of it, or of the origin's distance, is rounding and dropped. A ray
// with a non-finite origin or direction, or no volumes, is lit throughout;
// t_min > t_max or NaN gives nothing.
void lit_intervals_from_shadows(const Ray& ray, double t_min, double t_max, double scale, bool no_volumes,
                                FunctionRef<void(const Vec3&, const Vec3&, std::vector<Interval>&)> collect_shadows,
                                std::vector<Interval>& out);

}  // namespace skylit
