// Which parts of a view ray lie in sunlight: the shadow volumes (shadow_volume.h) of the
// scene's triangles for the sun, a directional light, clipped against the ray in closed
// form. Kaneda et al. 1991 §5 integrates light beams (sunlight scattered by fog) only
// over these sunlit sections of the viewing line; because the sections are exact, beams
// show neither sampling noise nor banding.
//
// Each casting triangle's volume is the semi-infinite prism swept by the triangle along
// -to_sun. A BVH over the prisms' footprints in the plane perpendicular to the sun
// (bvh_2d.h) finds the few prisms a ray can meet. docs/geometry.md, "Shadow volumes".
#pragma once

#include <cstddef>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/bvh_2d.h"
#include "skylit/geometry/intervals.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/geometry/shadow_volume.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

class SunShadowVolumes {
 public:
  // Builds the shadow volumes of the meshes (world coordinates) for sunlight arriving
  // from `to_sun` (toward the sun; need not be unit length). Every triangle casts a
  // shadow whichever way it is wound, as with RayTracer::occluded, so open meshes
  // (single walls, ground planes) shadow too; a closed, consistently wound mesh uses
  // only its sun-facing half, which casts the same shadow. Throws
  // std::invalid_argument for a zero or non-finite to_sun, a vertex index out of
  // range, a non-finite coordinate or a null mesh pointer.
  SunShadowVolumes(const std::vector<TriangleMesh>& meshes, const Vec3& to_sun);
  // The same without copying meshes held elsewhere (e.g. in render/Scene objects).
  SunShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& to_sun);

  // The parts of origin + t direction, t in [t_min, t_max], that are in sunlight (in no
  // shadow volume): sorted, disjoint, separated by shadow. ray.t_min / ray.t_max are
  // not used here. t_max may be infinite. Pieces of sunlight or shadow shorter than
  // 1e-9 of the scene's size are rounding and are dropped. A ray with a non-finite
  // origin or direction meets no volume (all sunlit, as RayTracer treats it as a
  // miss); t_min > t_max or NaN gives nothing. Const and safe from many threads;
  // the result depends only on the input.
  std::vector<Interval> sunlit_intervals(const Ray& ray, double t_min, double t_max) const;
  // The same over [ray.t_min, ray.t_max].
  std::vector<Interval> sunlit_intervals(const Ray& ray) const;
  // The same into `out` (cleared first), which a caller can reuse to avoid allocation.
  void sunlit_intervals(const Ray& ray, double t_min, double t_max, std::vector<Interval>& out) const;

  // Total sunlit length in t units (sum of sunlit_intervals' lengths).
  double sunlit_length(const Ray& ray, double t_min, double t_max) const;

  // Number of prisms (casting triangles) built.
  size_t volume_count() const { return prisms_.size(); }
  // The unit vector toward the sun.
  const Vec3& to_sun() const { return w_; }

 private:
  void build(const std::vector<const TriangleMesh*>& meshes, const Vec3& to_sun);

  Vec3 w_, u_, v_;                    // light frame: w toward the sun, u and v across
  double scale_ = 1;                  // largest coordinate magnitude of the casting triangles, >= 1 m
  std::vector<ShadowVolume> prisms_;  // in BVH leaf order
  std::vector<Bvh2dNode> nodes_;      // over the prisms' footprints in (u, v), tops along w
};

}  // namespace skylit
