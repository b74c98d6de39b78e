// Triangulation of simple polygons, convex or concave, with or without holes, by
// ear clipping (the method of D. Eberly, "Triangulation by Ear Clipping", Geometric
// Tools, 2002: holes are first joined to the outer ring by bridge edges, then ears
// are cut off one by one). Every reader that meets polygons uses it: OBJ faces now,
// CityJSON / CityGML surfaces later.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

struct Point2 {
  double x = 0;
  double y = 0;
};

// A polygon in a plane: its outer ring, then its holes. Rings are not closed (the
// first point is not repeated) and may be given in either orientation.
struct Polygon2 {
  std::vector<Point2> outer;
  std::vector<std::vector<Point2>> holes;
};

using TriangleIndices = std::array<uint32_t, 3>;

// Triangles covering the polygon, as indices into its points numbered outer ring
// first, then each hole in order. Each triangle turns the same way as the outer
// ring as given. Rings with fewer than three points give no triangles; a hole with
// fewer than three points is ignored. A self-intersecting or degenerate input still
// gives triangles (never a hang), but their union is then not guaranteed to be the
// polygon.
std::vector<TriangleIndices> triangulate_polygon(const Polygon2& polygon);

// A planar (or nearly planar) polygon in space: rings of points in 3D, outer first.
// The rings are projected onto the plane of the outer ring's Newell normal and
// triangulated there; triangles are indexed as in triangulate_polygon and face the
// way the outer ring turns (counter-clockwise seen from its normal's side).
std::vector<TriangleIndices> triangulate_polygon_3d(const std::vector<std::vector<Vec3>>& rings);

// The Newell normal of a ring: its length is twice the ring's area projected on the
// plane it defines (0 for a degenerate ring); points the way the ring turns
// counter-clockwise.
Vec3 newell_normal(const std::vector<Vec3>& ring);

}  // namespace skylit
