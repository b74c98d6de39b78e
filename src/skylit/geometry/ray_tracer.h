// Ray queries against the scene's triangle meshes: nearest hit for camera and
// bounce rays, any hit for shadow and sky-occlusion rays. Embree does the work
// behind this interface, so no Embree header is seen by users of the library.
#pragma once

#include <algorithm>
#include <cmath>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// A ray segment origin + t direction for t in [t_min, t_max]. The direction need
// not be unit; t is then in units of its length. Embree traces in single
// precision, so keep t_min a little above 0 for rays leaving a surface. A ray with
// a non-finite origin or direction, or t_min > t_max, hits nothing.
struct Ray {
  Vec3 origin;
  Vec3 direction;
  double t_min = 0;
  double t_max = std::numeric_limits<double>::infinity();
};

// The origin for a ray leaving a surface at `point` on the side of `normal`. Embree
// works in single precision, so a hit point is known to about 1e-7 of the coordinates'
// magnitude; the offset stays well above that, so the ray does not hit its own surface.
inline Vec3 offset_from_surface(const Vec3& point, const Vec3& normal) {
  const double magnitude = std::max({std::abs(point.x), std::abs(point.y), std::abs(point.z)});
  return point + (1e-4 + 2e-6 * magnitude) * normal;
}

struct Hit {
  double t;
  // Unit normal of the triangle in world space, cross(v1 - v0, v2 - v0) normalised
  // (counter-clockwise side); not flipped toward the ray.
  Vec3 geometric_normal;
  uint32_t mesh_id;   // as returned by RayTracer::add_mesh
  uint32_t triangle;  // index into that mesh's triangles
  // Barycentrics: the hit point is (1 - u - v) v0 + u v1 + v v2.
  float u, v;
};

// Which hits on a mesh count, for meshes with holes cut by a texture (alpha-masked
// foliage cards, railings) and faces that are seen from one side only. Called by the
// tracer's threads at once, so it must only read.
class HitFilter {
 public:
  virtual ~HitFilter() = default;
  // Whether a ray along `direction` meeting `triangle` at barycentrics (u, v) (as in Hit)
  // stops there; `shadow` for occluded() queries (shadow and sky-occlusion rays),
  // otherwise intersect() (camera and bounce rays). `geometric_normal` is the
  // triangle's cross(v1 - v0, v2 - v0), not normalised.
  virtual bool accepts(uint32_t triangle, float u, float v, const Vec3& direction, const Vec3& geometric_normal,
                       bool shadow) const = 0;
};

class RayTracer {
 public:
  // Throws std::runtime_error if Embree cannot start.
  RayTracer();
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;
  RayTracer(RayTracer&&) noexcept;
  RayTracer& operator=(RayTracer&&) noexcept;

  // Adds a mesh (world coordinates) and returns its id: 0, 1, 2, ... in call order.
  // An empty mesh gets an id and contributes nothing. Degenerate triangles are
  // kept (so triangle indices match the mesh) and are never hit. Throws
  // std::invalid_argument for an index out of range or a coordinate that is not a
  // finite single-precision number, std::runtime_error if Embree fails.
  // With a `filter` (which must outlive the tracer), hits it refuses are passed through
  // as if the triangle were not there; null: every hit counts (no cost per ray).
  uint32_t add_mesh(const TriangleMesh& mesh, const HitFilter* filter = nullptr);

  // Builds the acceleration structure. After this, intersect / occluded may be
  // called from any number of threads at once. Adding meshes afterwards needs
  // another commit before the next query.
  void commit();

  // Nearest hit with t in [t_min, t_max]. Throws std::logic_error before commit().
  std::optional<Hit> intersect(const Ray& ray) const;
  // Whether anything is hit with t in [t_min, t_max]; cheaper than intersect.
  // Throws std::logic_error before commit().
  bool occluded(const Ray& ray) const;

  // The same for many rays at once, traced in Embree's packets: hits[i] (resized to
  // rays.size()) is what intersect(rays[i]) gives, up to single-precision rounding
  // (docs/geometry.md). Faster where neighbouring rays are coherent: they share an
  // origin and point in nearby directions, as the rays of one surface point toward
  // neighbouring sky elements do.
  void intersect(std::span<const Ray> rays, std::vector<std::optional<Hit>>& hits) const;

  // intersect() and occluded() calls since construction, from all threads (for the
  // benchmark's rays per second).
  uint64_t rays_traced() const;

  size_t triangle_count() const;
  size_t mesh_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skylit
