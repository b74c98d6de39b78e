// Terrain as a height field: the height of a terrain mesh (a TIN relief or a DEM, in
// the scene's local frame) above any point of the plane, and the vertical shift that
// sets a building down on it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

class TerrainSurface {
 public:
  // The mesh's triangles, indexed by a uniform grid over their horizontal extent
  // (about one triangle per cell). Vertical triangles (zero area seen from above) are
  // left out: they have no height to give.
  explicit TerrainSurface(const TriangleMesh& terrain);

  // The terrain's height at (x, y): z of the triangle above or below the point (the
  // highest one where the mesh overlaps itself); nullopt outside the terrain.
  std::optional<double> height_at(double x, double y) const;

 private:
  TriangleMesh mesh_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<uint32_t> cell_start_;  // nx·ny + 1 offsets into cell_triangles_
  std::vector<uint32_t> cell_triangles_;
};

// Horizontal spacing of the points along a ground surface's edges at which the terrain
// is compared (besides its corners): a terrain ridge or hollow that an edge crosses
// between corners is seen to within its slope change over this length.
inline constexpr double kGroundSampleSpacingM = 0.25;

// The vertical shift that sets a building down on the terrain: its ground-surface
// rings (their corners and points every kGroundSampleSpacingM along their edges) are
// compared with the terrain below, and the building is moved so that the point that
// stands highest above the terrain touches it. No part of its ground then floats; on
// a slope a flat floor sinks into the uphill terrain as a real foundation does. Where
// the ground surface follows the terrain (PLATEAU's LoD2 ground surfaces lie at the
// footprint's lowest terrain height; a ground that follows a plane), every point meets
// it. nullopt when no point lies over the terrain.
std::optional<double> seating_shift_m(const TerrainSurface& terrain,
                                      const std::vector<std::vector<Vec3>>& ground_rings);

// The same for a placed building's mesh: its ground triangles (is_ground, one flag per
// triangle) are its ground surface, or without any the edges along its lowest point
// (walls of a block with an open bottom); every vertex is moved by the shift, which is
// returned (nullopt, nothing moved, when no ground lies over the terrain).
std::optional<double> seat_on_terrain(const TerrainSurface& terrain, TriangleMesh& building,
                                      const std::vector<bool>& is_ground);

}  // namespace skylit
