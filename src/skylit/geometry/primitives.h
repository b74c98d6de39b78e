// Simple shapes a scene can describe without a mesh file: boxes (buildings,
// blocks) and a ground square. All in world metres, z up, outward winding.
#pragma once

#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// Axis-aligned box between two corners: 8 vertices, 12 triangles, normals outward.
// Throws std::invalid_argument unless min <= max in every axis and all are finite
// (a flat box, min == max in one axis, is allowed).
TriangleMesh make_box(Vec3 min, Vec3 max);

// Box of the given size (x, y, z extents in metres) centred on `center` (the centre
// of the box, not of its base), then turned by rotation_z_deg about the vertical
// axis through `center` (positive = counter-clockwise seen from above).
TriangleMesh make_box_centered(Vec3 center, Vec3 size, double rotation_z_deg);

// Horizontal square of side size_m centred on `center` at height center.z;
// 2 triangles whose geometric normal is +z. Throws std::invalid_argument unless
// size_m > 0 and finite.
TriangleMesh make_ground_plane(Vec3 center, double size_m);

}  // namespace skylit
