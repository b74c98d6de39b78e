// Which parts of a view ray lie in sunlight: the shadow volumes (Crow 1977, "Shadow
// algorithms for computer graphics", SIGGRAPH '77, Comput Graph 11(2):242-247) of
// the scene's triangles for the sun, a directional light, clipped against the ray
// in closed form. Kaneda et al. 1991 §5 integrates light beams (sunlight scattered
// by fog) only over these sunlit sections of the viewing line; because the sections
// are exact, beams show neither sampling noise nor banding.
//
// Method (docs/geometry.md, "Shadow volumes"): each casting triangle's volume is the
// semi-infinite prism swept by the triangle along -to_sun, the intersection of four
// half-spaces (three sides through its edges, and the triangle's plane). A ray meets
// a convex prism in one interval, found by clipping; the shadow is the union of the
// intervals and the sunlight is its complement. A BVH over the prisms' footprints
// in the plane perpendicular to the sun finds the few prisms a ray can meet.
//
// A point light (a street lamp, a headlight) works the same way with frusta for
// prisms: each casting triangle's volume is bounded by the three planes through the
// light and its edges and by its own plane, so the same clipping gives exact lit
// intervals. The prism BVH needs a single direction of light; for a point light the
// volumes are tested one by one after a bounding-sphere test on the part of the ray
// beyond each triangle (night scenes have few casting triangles per lamp).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/geometry/triangle_mesh.h"
#include "skylit/core/vec3.h"

namespace skylit {

// A closed range [begin, end] of the ray parameter t (units of the direction's length).
struct Interval {
  double begin;
  double end;
};

class ShadowVolumes {
 public:
  // Builds the shadow volumes of the meshes (world coordinates) for sunlight arriving
  // from `to_sun` (toward the sun; need not be unit length). Every triangle casts a
  // shadow whichever way it is wound, as with RayTracer::occluded, so open meshes
  // (single walls, ground planes) shadow too; a closed, consistently wound mesh uses
  // only its sun-facing half, which casts the same shadow. Throws
  // std::invalid_argument for a zero or non-finite to_sun, a vertex index out of
  // range, a non-finite coordinate or a null mesh pointer.
  ShadowVolumes(const std::vector<TriangleMesh>& meshes, const Vec3& to_sun);
  // The same without copying meshes held elsewhere (e.g. in render/Scene objects).
  ShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& to_sun);
  // The shadow volumes for a point light at `light` (world coordinates, finite) that
  // shines only within `max_gamma_deg` of the unit vector `aim` (180: everywhere).
  // Triangles wholly outside that cone cast no volume: their shadow lies where the
  // light does not go.
  static ShadowVolumes for_point_light(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                                       const Vec3& aim = {0, 0, -1}, double max_gamma_deg = 180);
  ~ShadowVolumes();
  ShadowVolumes(ShadowVolumes&&) noexcept;
  ShadowVolumes& operator=(ShadowVolumes&&) noexcept;
  ShadowVolumes(const ShadowVolumes&) = delete;
  ShadowVolumes& operator=(const ShadowVolumes&) = delete;

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
  size_t volume_count() const;
  // The unit vector toward the sun (for a point light: meaningless).
  const Vec3& to_sun() const;

 private:
  struct Data;
  explicit ShadowVolumes(std::unique_ptr<const Data> data);
  static std::unique_ptr<const Data> build(const std::vector<const TriangleMesh*>& meshes, const Vec3& to_sun);
  static std::unique_ptr<const Data> build_point(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                                                 const Vec3& aim, double max_gamma_deg);
  std::unique_ptr<const Data> data_;
};

}  // namespace skylit
