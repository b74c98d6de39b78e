// Box and ground-plane meshes (see primitives.h).
#include "skylit/geometry/primitives.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skylit/geometry/transform.h"

namespace skylit {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

TriangleMesh make_box(Vec3 min, Vec3 max) {
  if (!finite(min) || !finite(max) || min.x > max.x || min.y > max.y || min.z > max.z)
    throw std::invalid_argument("make_box: need finite corners with min <= max in every axis");
  TriangleMesh mesh;
  // Vertex i has x from bit 0, y from bit 1, z from bit 2 (0 = min, 1 = max).
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
  // Two triangles per face, counter-clockwise seen from outside.
  mesh.triangles = {
      {0, 4, 6}, {0, 6, 2},  // -x
      {1, 3, 7}, {1, 7, 5},  // +x
      {0, 1, 5}, {0, 5, 4},  // -y
      {2, 6, 7}, {2, 7, 3},  // +y
      {0, 2, 3}, {0, 3, 1},  // -z
      {4, 5, 7}, {4, 7, 6},  // +z
  };
  return mesh;
}

TriangleMesh make_box_centered(Vec3 center, Vec3 size, double rotation_z_deg) {
  if (!std::isfinite(rotation_z_deg)) throw std::invalid_argument("make_box_centered: rotation is not finite");
  // Build around the origin so the rotation turns the box about its own axis.
  const Vec3 half = size * 0.5;
  const TriangleMesh box = make_box(-half, half);
  return transformed(box, Transform::translation(center) * Transform::rotation_z_deg(rotation_z_deg));
}

TriangleMesh make_ground_plane(Vec3 center, double size_m) {
  if (!finite(center) || !(size_m > 0) || !std::isfinite(size_m))
    throw std::invalid_argument("make_ground_plane: need a finite centre and size_m > 0");
  const double h = size_m * 0.5;
  TriangleMesh mesh;
  mesh.vertices = {{center.x - h, center.y - h, center.z},
                   {center.x + h, center.y - h, center.z},
                   {center.x + h, center.y + h, center.z},
                   {center.x - h, center.y + h, center.z}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

}  // namespace skylit
