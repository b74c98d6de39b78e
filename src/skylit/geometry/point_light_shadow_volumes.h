// Which parts of a view ray a point light (a street lamp, a headlight) reaches: the
// shadow volumes (shadow_volume.h) of the scene's triangles for that light, clipped
// against the ray in closed form, so the lamp's glow in fog (media/lamp_in_scatter.h)
// shows exact beams and shadows without sampling noise.
//
// The triangles are first gathered into convex coplanar faces (convex_faces.h). Each
// casting face's volume is the frustum bounded by the planes through the light and its
// edges and by its own plane. The faces are listed on a cube map of the light's
// directions (light_direction_cells.h): a view ray's piece, walked cell by cell, clips
// only the frusta of the cells where it passes beyond the nearest face, so a query
// meets the few faces that may shadow it rather than all of them (a city block gives
// a lamp tens of thousands). docs/geometry.md, "Shadow volumes".
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/convex_faces.h"
#include "skylit/geometry/intervals.h"
#include "skylit/geometry/light_direction_cells.h"
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
  Vec3 light_;
  double scale_ = 1;  // largest coordinate magnitude of the light and the casting triangles, >= 1 m
  // A frustum: planes [first_plane, first_plane + sides] of planes_, the cap last.
  struct Frustum {
    uint32_t first_plane, sides;
  };
  std::vector<Frustum> frusta_;
  std::vector<HalfSpace> planes_;
  LightDirectionCells cells_;  // frusta by the directions of their faces
};

}  // namespace skylit
