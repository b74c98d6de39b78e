// The meshes that cast shadow volumes (sun_shadow_volumes.h, point_light_shadow_volumes.h):
// the checks on their input, and which of a mesh's triangles need cast at all. Both
// light kinds ask the same of a mesh, so it is said once here.
#pragma once

#include <cstddef>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

bool is_finite(const Vec3& v);
// The largest |coordinate|: the scale that rounding is measured against.
double max_abs(const Vec3& v);
// A total order on points, so that a plane through two points can be built from them in
// one canonical order (bit-identical for the two triangles sharing an edge).
bool lexicographic_less(const Vec3& a, const Vec3& b);

// Mesh `id`, checked: not null, finite, indices in range. Throws std::invalid_argument,
// naming `who` (the class building volumes) and the mesh.
const TriangleMesh& checked_mesh(const std::vector<const TriangleMesh*>& meshes, size_t id, const char* who);

// Which triangles of a mesh cast. A closed surface: a ray from outside toward the light
// that meets it leaves it through a triangle facing the light (winding numbers: it
// must cross outward as often as inward), so those triangles alone cast the whole
// shadow. The volume's sign says which way "outward" is wound. Otherwise every
// triangle casts. +1: triangles whose normal faces the light; −1: away; 0: all.
int casting_side(const TriangleMesh& mesh);

}  // namespace skylit
