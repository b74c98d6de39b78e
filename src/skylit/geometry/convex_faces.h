// A mesh's triangles gathered into convex polygons: neighbours (sharing an edge, by
// position) that lie in one plane and wind the same way join, and a group whose
// convex hull covers exactly their area becomes that hull. A wall tessellated into
// panels becomes one rectangle again. A point light's shadow volumes
// (point_light_shadow_volumes.h) then need one frustum per polygon rather than per
// triangle: the shadow of a union of coplanar pieces is the union of their shadows.
#pragma once

#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

struct ConvexFace {
  std::vector<Vec3> corners;  // counter-clockwise about `normal`, no three in line (triangles: as given)
  Vec3 normal;                // unit, the triangles' geometric normal (triangle_mesh.h)
};

// Every triangle of `mesh` lies in exactly one face; degenerate triangles and groups
// that are not convex stay single triangles. Coplanar means normals within 1e-12 and
// planes within 1e-9 of the mesh's size: rounding, not geometry.
std::vector<ConvexFace> convex_faces(const TriangleMesh& mesh);

}  // namespace skylit
