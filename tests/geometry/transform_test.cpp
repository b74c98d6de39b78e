// Transforms: rotation senses and order, composition order, glTF matrix layout and
// quaternions, and winding kept outward under mirroring.
#include "skylit/geometry/transform.h"

#include <gtest/gtest.h>

#include "skylit/geometry/primitives.h"

namespace skylit {
namespace {

void expect_near(Vec3 a, Vec3 b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Transform, RotationZTurnsEastTowardNorth) {
  // Right-handed about +z: east (+x) goes to north (+y); exact at 90°.
  EXPECT_EQ(Transform::rotation_z_deg(90).apply_point({1, 0, 0}), Vec3(0, 1, 0));
  EXPECT_EQ(Transform::rotation_z_deg(-90).apply_point({1, 0, 0}), Vec3(0, -1, 0));
  expect_near(Transform::rotation_z_deg(30).apply_point({1, 0, 0}), {std::sqrt(3.0) / 2, 0.5, 0});
}

TEST(Transform, RotationXyzAppliesXThenYThenZ) {
  // x first takes north to up, which a z turn then leaves alone; z first would
  // take north to west and the x turn would leave that alone.
  expect_near(Transform::rotation_xyz_deg({90, 0, 90}).apply_point({0, 1, 0}), {0, 0, 1});
  // y then z: east → down (Ry(90) takes +x to -z) → still down.
  expect_near(Transform::rotation_xyz_deg({0, 90, 90}).apply_point({1, 0, 0}), {0, 0, -1});
}

TEST(Transform, CompositionAppliesRightOperandFirst) {
  const Transform t = Transform::translation({10, 0, 0}) * Transform::scale({2, 3, 4});
  EXPECT_EQ(t.apply_point({1, 1, 1}), Vec3(12, 3, 4));
  EXPECT_EQ(t.apply_vector({1, 1, 1}), Vec3(2, 3, 4));
  EXPECT_DOUBLE_EQ(t.determinant(), 24.0);
}

TEST(Transform, QuaternionMatchesAxisRotation) {
  const double s = std::sqrt(0.5);
  const Transform q = Transform::rotation_quaternion(0, 0, s, s);  // 90° about z
  expect_near(q.apply_point({1, 2, 3}), Transform::rotation_z_deg(90).apply_point({1, 2, 3}));
  // Not normalised: same rotation.
  expect_near(Transform::rotation_quaternion(0, 0, 2, 2).apply_point({1, 2, 3}), {-2, 1, 3});
  EXPECT_THROW(Transform::rotation_quaternion(0, 0, 0, 0), std::invalid_argument);
}

TEST(Transform, ColumnMajorMatrixPutsTranslationInLastColumn) {
  // glTF stores the translation in elements 12, 13, 14.
  const std::array<double, 16> c{2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 5, 6, 7, 1};
  EXPECT_EQ(Transform::from_column_major_4x4(c).apply_point({1, 1, 1}), Vec3(7, 8, 9));
}

TEST(Transform, MirroringKeepsOutwardWinding) {
  const TriangleMesh box = make_box({-1, -1, -1}, {1, 1, 1});
  const TriangleMesh mirrored = transformed(box, Transform::scale({-1, 1, 1}));
  for (const auto& t : mirrored.triangles) {
    const Vec3 a = mirrored.vertices[t[0]], b = mirrored.vertices[t[1]], c = mirrored.vertices[t[2]];
    EXPECT_GT(dot(cross(b - a, c - a), (a + b + c) / 3.0), 0.0);
  }
}

}  // namespace
}  // namespace skylit
