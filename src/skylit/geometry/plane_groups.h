// The planes of a mesh: its triangles grouped by the plane they lie in, so that what
// belongs to a surface (a wall, a roof face) does not depend on how it was cut into
// triangles. A wall exported from a CAD model around its windows comes as dozens of
// long, thin triangles; cut into strips of 1 m or 0.1 m, a street canyon's sunlit wall
// lit its shaded neighbour 7 % too brightly or 18 % too dimly when the obstacles' sky
// light was kept per triangle (render/obstacle_sky_light.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// One orientation per plane, whichever side a triangle was wound on: z > 0, or z = 0
// and y > 0, or z = y = 0 and x > 0.
Vec3 canonical_plane_normal(const Vec3& n);

// The plane n·x = offset (n canonical) rounded to its tolerance: the normal's
// components to 1e-4 and the offset to 1 mm (far below any facade's size).
std::array<long long, 4> rounded_plane(const Vec3& n, double offset);

// The plane a triangle lies in: n·x = offset with n canonical, and the triangle's area.
struct TrianglePlane {
  Vec3 normal;
  double offset = 0;
  double area_m2 = 0;
};
// Triangle `t` of `mesh`'s plane; none for a degenerate triangle.
std::optional<TrianglePlane> triangle_plane(const TriangleMesh& mesh, size_t t);

class PlaneGroups {
 public:
  // One plane: its triangles' common unit normal (one orientation per plane, whichever
  // side a triangle was wound on), an orthonormal frame in it, and its triangles' area.
  struct Plane {
    Vec3 normal;         // canonical: z > 0, or z = 0 and y > 0, or z = y = 0 and x > 0
    Vec3 origin;         // the point of the plane nearest the coordinates' origin
    Vec3 e1, e2;         // in the plane, e1 × e2 = normal, e1 level (along x in a level plane)
    double area_m2 = 0;  // the sum of its triangles' areas
  };

  // Triangles lie in one plane when their unit normals agree to 1e-4 and their planes'
  // offsets to 1 mm (the tolerance of a model's coordinates, far below any facade's
  // size); degenerate triangles lie in none.
  explicit PlaneGroups(const TriangleMesh& mesh);

  // The plane of triangle `t`, or −1 for a degenerate one.
  int32_t of(uint32_t t) const { return plane_of_triangle_[t]; }
  const Plane& plane(int32_t p) const { return planes_[static_cast<size_t>(p)]; }
  size_t size() const { return planes_.size(); }

 private:
  std::vector<int32_t> plane_of_triangle_;
  std::vector<Plane> planes_;
};

}  // namespace skylit
