// Primitive meshes: outward winding, closed box surface, rotated corners, plane normal.
#include "skylit/geometry/primitives.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace skylit {
namespace {

Vec3 normal_of(const TriangleMesh& m, const std::array<uint32_t, 3>& t) {
  return cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
}

bool has_vertex(const TriangleMesh& m, Vec3 p, double tol = 1e-9) {
  return std::any_of(m.vertices.begin(), m.vertices.end(), [&](const Vec3& v) { return length(v - p) <= tol; });
}

TEST(Primitives, BoxHasTwelveOutwardTrianglesCoveringItsSurface) {
  const Vec3 lo{1, 2, 3}, hi{4, 6, 8};  // 3 x 4 x 5
  const TriangleMesh box = make_box(lo, hi);
  ASSERT_EQ(box.triangles.size(), 12u);
  ASSERT_EQ(box.vertices.size(), 8u);
  const Vec3 centre = (lo + hi) * 0.5;
  double area = 0;
  Vec3 sum{0, 0, 0};
  for (const auto& t : box.triangles) {
    const Vec3 n = normal_of(box, t);
    const Vec3 mid = (box.vertices[t[0]] + box.vertices[t[1]] + box.vertices[t[2]]) / 3.0;
    EXPECT_GT(dot(n, mid - centre), 0.0) << "inward triangle";
    area += 0.5 * length(n);
    sum += n;
  }
  EXPECT_DOUBLE_EQ(area, 2 * (3 * 4 + 4 * 5 + 3 * 5));
  // A closed surface's area vectors cancel.
  EXPECT_NEAR(length(sum), 0.0, 1e-12);
}

TEST(Primitives, RotatedBoxCornersAreWhereExpected) {
  const Vec3 c{10, 20, 5};
  const TriangleMesh box = make_box_centered(c, {4, 2, 10}, 30);
  ASSERT_EQ(box.triangles.size(), 12u);
  const double cs = std::cos(radians(30)), sn = std::sin(radians(30));
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0})
      for (double sz : {-1.0, 1.0}) {
        const double x = 2 * sx, y = 1 * sy;
        const Vec3 expected{c.x + x * cs - y * sn, c.y + x * sn + y * cs, c.z + 5 * sz};
        EXPECT_TRUE(has_vertex(box, expected)) << expected.x << " " << expected.y << " " << expected.z;
      }
  // 90°: the 4 m east-west extent now runs north-south, exactly.
  const TriangleMesh turned = make_box_centered(c, {4, 2, 10}, 90);
  EXPECT_TRUE(has_vertex(turned, {9, 18, 0}, 0));
  EXPECT_TRUE(has_vertex(turned, {11, 22, 10}, 0));
}

TEST(Primitives, GroundPlaneFacesUp) {
  const TriangleMesh plane = make_ground_plane({5, -5, 0.5}, 100);
  ASSERT_EQ(plane.triangles.size(), 2u);
  double area = 0;
  for (const auto& t : plane.triangles) {
    const Vec3 n = normal_of(plane, t);
    EXPECT_GT(n.z, 0.0);
    EXPECT_EQ(n.x, 0.0);
    EXPECT_EQ(n.y, 0.0);
    area += 0.5 * length(n);
  }
  EXPECT_DOUBLE_EQ(area, 100.0 * 100.0);
  for (const Vec3& v : plane.vertices) EXPECT_EQ(v.z, 0.5);
  EXPECT_TRUE(has_vertex(plane, {-45, -55, 0.5}, 0));
  EXPECT_TRUE(has_vertex(plane, {55, 45, 0.5}, 0));
}

TEST(Primitives, RejectsInvertedOrNonFiniteSizes) {
  EXPECT_THROW(make_box({0, 0, 1}, {1, 1, 0}), std::invalid_argument);
  EXPECT_THROW(make_box_centered({0, 0, 0}, {1, -1, 1}, 0), std::invalid_argument);
  EXPECT_THROW(make_box_centered({0, 0, 0}, {1, 1, 1}, std::nan("")), std::invalid_argument);
  EXPECT_THROW(make_ground_plane({0, 0, 0}, 0), std::invalid_argument);
  EXPECT_THROW(make_ground_plane({0, std::nan(""), 0}, 10), std::invalid_argument);
}

TEST(Primitives, AppendReindexesTriangles) {
  TriangleMesh a = make_ground_plane({0, 0, 0}, 1);
  a.append(make_box({0, 0, 0}, {1, 1, 1}));
  ASSERT_EQ(a.vertices.size(), 12u);
  ASSERT_EQ(a.triangles.size(), 14u);
  EXPECT_EQ(a.triangles[2][0], 4u);  // first box triangle {0,4,6} moved by 4
  EXPECT_EQ(a.triangles[2][1], 8u);
}

}  // namespace
}  // namespace skylit
