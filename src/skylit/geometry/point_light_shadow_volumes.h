// Which parts of a view ray a point light (a street lamp, a headlight) reaches: the
// shadow volumes (shadow_volume.h) of the scene's triangles for that light, clipped
// against the ray in closed form, so the lamp's glow in fog (media/lamp_in_scatter.h)
// shows exact beams and shadows without sampling noise.
//
// Each casting triangle's volume is the frustum bounded by the three planes through the
// light and its edges and by its own plane. A BVH like the sun's needs a single
// direction of light; here the frusta are tested in small groups, each behind a cone
// from the light around the group's bounding sphere (night scenes have few casting
// triangles per lamp). docs/geometry.md, "Shadow volumes".
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/intervals.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/geometry/shadow_volume.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

class PointLightShadowVolumes {
 public:
  // The shadow volumes for a point light at `light` (world coordinates, finite) that
  // shines only within `max_gamma_deg` of the unit vector `aim` (180: everywhere).
  // Triangles wholly outside that cone cast no volume: their shadow lies where the
  // light does not go. Which triangles cast, and the checks on the meshes, are as for
  // SunShadowVolumes (std::invalid_argument for a non-finite light or bad mesh).
  PointLightShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                          const Vec3& aim = {0, 0, -1}, double max_gamma_deg = 180);

  // The parts of origin + t direction, t in [t_min, t_max], in no shadow volume of the
  // light (lit if the light shines there), with the conventions of
  // SunShadowVolumes::sunlit_intervals. Const and safe from many threads.
  std::vector<Interval> lit_intervals(const Ray& ray, double t_min, double t_max) const;
  // The same into `out` (cleared first), which a caller can reuse to avoid allocation.
  void lit_intervals(const Ray& ray, double t_min, double t_max, std::vector<Interval>& out) const;

  // Number of frusta (casting triangles) built.
  size_t volume_count() const { return frusta_.size(); }

 private:
  // Frusta [begin, end), all inside a cone from the light.
  struct Group {
    Vec3 axis;        // unit, from the light toward the group's bounding sphere
    double sin_half;  // of the cone's half-angle; ≥ 1: the light is inside the sphere
    uint32_t begin, end;
  };

  Vec3 light_;
  double scale_ = 1;                  // largest coordinate magnitude of the light and the casting triangles, >= 1 m
  std::vector<ShadowVolume> frusta_;  // in mesh order
  std::vector<Group> groups_;
};

}  // namespace skylit
