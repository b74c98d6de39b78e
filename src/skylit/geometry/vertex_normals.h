// Smooth shading normals for meshes that were modelled as smooth but arrive as flat
// triangles: at each corner, the angle-weighted mean of the normals of the triangles
// around that point whose normals lie within a crease angle of this triangle's (the
// rule of 3D modelling tools' "auto smooth"), so that hard edges stay hard.
#pragma once

#include <array>
#include <vector>

#include "skylit/geometry/transform.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// Unit normals at a triangle's three corners, on its counter-clockwise side.
using CornerNormals = std::array<std::array<float, 3>, 3>;

// Per triangle of `mesh`. Corners are grouped by position (exactly equal coordinates),
// so meshes whose vertices are split at seams are smoothed across them too. Degenerate
// triangles take no part and get their neighbours' or +z. A crease angle of 0 gives
// every corner its triangle's own normal.
std::vector<CornerNormals> crease_angle_normals(const TriangleMesh& mesh, double crease_angle_deg);

// A file's own corner normals (glTF NORMAL, OBJ vn) made safe to shade with: a corner
// whose normal is missing, zero or not finite takes its triangle's geometric normal
// (flat there, as glTF asks for absent normals), and one on the far side of its
// triangle's counter-clockwise face is turned over (files whose winding and normals
// disagree), so the result is a unit vector on the triangle's counter-clockwise side
// everywhere. A degenerate triangle gets +z.
void sanitize_file_normals(const TriangleMesh& mesh, std::vector<CornerNormals>& normals);

// Corner normals carried through a transform (as `transformed` moves the mesh): turned
// by the inverse transpose, and corners 1 and 2 swapped under a mirror, as the
// triangles' corners are.
void transform_corner_normals(std::vector<CornerNormals>& normals, const Transform& transform);

// Whether any corner differs from its triangle's geometric normal by more than
// `tolerance_deg` (a mesh that is flat everywhere needs no normals).
bool any_smooth_corner(const TriangleMesh& mesh, const std::vector<CornerNormals>& normals, double tolerance_deg);

// The point from which a smooth-shaded triangle's shadow rays should leave (J. Hanika,
// "Hacking the shadow terminator", Ray Tracing Gems II, 2021, ch. 4): the hit point
// p = Σ b_i p_i lifted onto the curved surface the normals describe, Σ b_i q_i with
// q_i = p − min(0, (p − p_i)·n_i) n_i, p projected up onto each corner's tangent plane
// where it lies below it. On a flat triangle (all n_i equal to its normal) q_i = p.
Vec3 shading_point(const std::array<Vec3, 3>& corners, const CornerNormals& normals, double b1, double b2);

}  // namespace skylit
