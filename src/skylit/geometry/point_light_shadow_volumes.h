// Which parts of a view ray a point light (a street lamp, a headlight) reaches: the
// shadow volumes (shadow_volume.h) of the scene's triangles for that light, clipped
// against the ray in closed form, so the lamp's glow in fog (media/lamp_in_scatter.h)
// shows exact beams and shadows without sampling noise.
//
// The triangles are first gathered into convex coplanar faces (convex_faces.h). Each
// casting face's volume is the frustum bounded by the planes through the light and its
// edges and by its own plane. The frusta sit in a hierarchy of cones from
// the light (each around the bounding sphere of its triangles, and no nearer to the
// light than that sphere): a view ray's piece is checked against a cone by the arc of
// directions under which the light sees the piece, and by its farthest point from the
// light, so a query visits the few frusta near the piece rather than all of them (a
// city block gives a lamp tens of thousands). docs/geometry.md, "Shadow volumes".
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/convex_faces.h"
#include "skylit/geometry/intervals.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/geometry/shadow_volume.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// A mesh's convex faces and which of them cast (casting_side, shadow_casters.h): made
// once for a scene and shared by its lamps.
struct ShadowCasterFaces {
  std::vector<ConvexFace> faces;
  int casting_side;
};
// The meshes checked as SunShadowVolumes checks them (std::invalid_argument).
std::vector<ShadowCasterFaces> shadow_caster_faces(const std::vector<const TriangleMesh*>& meshes);

class PointLightShadowVolumes {
 public:
  // The shadow volumes for a point light at `light` (world coordinates, finite) that
  // shines only within `max_gamma_deg` of the unit vector `aim` (180: everywhere).
  // Faces wholly outside that cone cast no volume: their shadow lies where the light
  // does not go. Which triangles cast, and the checks on the meshes, are as for
  // SunShadowVolumes (std::invalid_argument for a non-finite light or bad mesh).
  // Faces wholly farther than `reach_m` from the light cast no volume either: their
  // shadows lie beyond it, where the caller looks for them otherwise or not at all.
  PointLightShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                          const Vec3& aim = {0, 0, -1}, double max_gamma_deg = 180,
                          double reach_m = std::numeric_limits<double>::infinity());
  // The same from faces made by shadow_caster_faces.
  PointLightShadowVolumes(const std::vector<ShadowCasterFaces>& meshes, const Vec3& light, const Vec3& aim,
                          double max_gamma_deg, double reach_m);

  // The parts of origin + t direction, t in [t_min, t_max], in no shadow volume of the
  // light (lit if the light shines there), with the conventions of
  // SunShadowVolumes::sunlit_intervals. Const and safe from many threads.
  std::vector<Interval> lit_intervals(const Ray& ray, double t_min, double t_max) const;
  // The same into `out` (cleared first), which a caller can reuse to avoid allocation.
  void lit_intervals(const Ray& ray, double t_min, double t_max, std::vector<Interval>& out) const;

  // Number of frusta (casting faces) built.
  size_t volume_count() const { return frusta_.size(); }

 private:
  // A node of the hierarchy: its frusta all lie inside a cone from the light, no nearer
  // to it than `nearest_m`. A leaf holds frusta [begin, end); an inner node's children
  // are the next node and node `second`.
  struct Node {
    Vec3 axis;                  // unit, from the light toward the node's bounding sphere
    double sin_half, cos_half;  // of the cone's half-angle; sin_half ≥ 1: the light is inside the sphere
    double nearest_m;           // from the light to the sphere
    double top_z;               // no frustum rises above it (+∞ unless the light is above all corners)
    uint32_t begin, end;        // leaves: the frusta
    uint32_t second;            // inner nodes: the second child (0 on leaves)
  };
  struct Caster;
  uint32_t build(std::vector<Caster>& casters, uint32_t begin, uint32_t end);
  // Whether the piece of o + t·dir between `near` and `far` (its ends less the light;
  // `far` a direction only when the piece is unbounded; `far_distance` the piece's
  // largest distance from the light, `lowest_z` its lowest height) may meet the node's
  // frusta.
  bool may_meet(const Node& node, const Vec3& plane_normal, double plane_normal_length, const Vec3& near,
                const Vec3& far, double far_distance, double lowest_z) const;

  Vec3 light_;
  double scale_ = 1;  // largest coordinate magnitude of the light and the casting triangles, >= 1 m
  // A frustum: planes [first_plane, first_plane + sides] of planes_, the cap last.
  struct Frustum {
    uint32_t first_plane, sides;
  };
  std::vector<Frustum> frusta_;  // in the hierarchy's order
  std::vector<HalfSpace> planes_;
  std::vector<Node> nodes_;  // depth first; the root first
};

}  // namespace skylit
