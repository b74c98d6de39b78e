// Affine transforms (world_from_object) for placing meshes: the scene file gives
// translation / rotation / scale per object, and glTF nodes give matrices or TRS.
#pragma once

#include <array>

#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// A 3x4 matrix [A | t] acting on points as A p + t. Rotations are right-handed
// (counter-clockwise looking down the axis toward the origin), angles in degrees.
struct Transform {
  // m[row][col]; column 3 is the translation.
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  static Transform identity() { return {}; }
  static Transform translation(Vec3 offset);
  static Transform scale(Vec3 factors);
  static Transform rotation_x_deg(double angle_deg);
  static Transform rotation_y_deg(double angle_deg);
  // About +z: positive turns east (+x) toward north (+y), i.e. counter-clockwise
  // seen from above, the opposite sense to a compass azimuth.
  static Transform rotation_z_deg(double angle_deg);
  // Rotation about x, then about y, then about z (fixed world axes): Rz * Ry * Rx.
  static Transform rotation_xyz_deg(Vec3 angles_deg);
  // Unit quaternion (x, y, z, w) as glTF stores it; normalised here, so any
  // non-zero quaternion is accepted. Throws std::invalid_argument for a zero one.
  static Transform rotation_quaternion(double x, double y, double z, double w);
  // A 4x4 matrix stored column by column (glTF's "matrix"); the last row is ignored
  // because glTF requires it to be (0, 0, 0, 1).
  static Transform from_column_major_4x4(const std::array<double, 16>& c);

  // Composition: (a * b).apply_point(p) == a.apply_point(b.apply_point(p)).
  Transform operator*(const Transform& other) const;
  Vec3 apply_point(Vec3 p) const;
  // Directions: the linear part only (no translation).
  Vec3 apply_vector(Vec3 v) const;
  // Surface normals: the inverse transpose of the linear part, so that a normal stays
  // perpendicular to its surface under non-uniform scaling, and points to the same side
  // of a closed surface under a mirror. Unit length; zero for a zero or singular case.
  Vec3 apply_normal(Vec3 n) const;
  // Determinant of the linear part; negative means the transform mirrors.
  double determinant() const;
};

// The mesh with every vertex transformed. A mirroring transform (negative
// determinant) would turn triangles inside out, so their winding is reversed to
// keep geometric normals pointing outward.
TriangleMesh transformed(const TriangleMesh& mesh, const Transform& world_from_object);

}  // namespace skylit
