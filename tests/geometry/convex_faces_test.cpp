// A mesh's triangles gathered into convex coplanar faces (geometry/convex_faces.h).
#include "skylit/geometry/convex_faces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "skylit/geometry/primitives.h"

namespace skylit {
namespace {

// A wall in the plane y = 0, x ∈ [0, columns], z ∈ [0, 1.5 rows], in panels whose four
// corners each are written anew (as an OBJ of panels comes), wound toward −y.
TriangleMesh panelled_wall(int columns, int rows) {
  TriangleMesh wall;
  for (int u = 0; u < columns; ++u)
    for (int k = 0; k < rows; ++k) {
      const auto n = static_cast<uint32_t>(wall.vertices.size());
      const double x = u, z = 1.5 * k;
      wall.vertices.insert(wall.vertices.end(), {{x, 0, z}, {x + 1, 0, z}, {x + 1, 0, z + 1.5}, {x, 0, z + 1.5}});
      wall.triangles.push_back({n, n + 1, n + 2});
      wall.triangles.push_back({n, n + 2, n + 3});
    }
  return wall;
}

TEST(ConvexFaces, PanelledWallBecomesOneRectangle) {
  const std::vector<ConvexFace> faces = convex_faces(panelled_wall(16, 8));
  ASSERT_EQ(faces.size(), 1U);
  const ConvexFace& face = faces[0];
  ASSERT_EQ(face.corners.size(), 4U);  // the points along its edges dropped
  EXPECT_NEAR(face.normal.y, -1, 1e-12);
  // Its corners are the wall's, counter-clockwise about the normal.
  for (const Vec3& c : face.corners) {
    EXPECT_TRUE(c.x == 0 || c.x == 16) << c.x;
    EXPECT_TRUE(c.z == 0 || c.z == 12) << c.z;
  }
  for (size_t i = 0; i < 4; ++i) {
    const Vec3 &a = face.corners[i], &b = face.corners[(i + 1) % 4], &c = face.corners[(i + 2) % 4];
    EXPECT_GT(dot(cross(b - a, c - b), face.normal), 0);
  }
}

TEST(ConvexFaces, NonConvexOrMixedGroupsStayTriangles) {
  // An L of three panels: its hull covers more than its area.
  TriangleMesh l_shape = panelled_wall(2, 2);
  l_shape.triangles.resize(6);  // panels (0, 0), (0, 1), (1, 0)
  EXPECT_EQ(convex_faces(l_shape).size(), 6U);
  // Two panels side by side, wound opposite ways: not one face.
  TriangleMesh flipped = panelled_wall(2, 1);
  for (size_t t = 2; t < 4; ++t) std::swap(flipped.triangles[t][1], flipped.triangles[t][2]);
  EXPECT_EQ(convex_faces(flipped).size(), 2U);  // a face per panel
  // Two panels at an angle (a corner of a building): two faces.
  TriangleMesh corner = panelled_wall(1, 1);
  corner.vertices.insert(corner.vertices.end(), {{1, 1, 0}, {1, 1, 1.5}});
  corner.triangles.push_back({1, 4, 5});
  corner.triangles.push_back({1, 5, 2});
  EXPECT_EQ(convex_faces(corner).size(), 2U);
  // A box: six rectangles.
  const std::vector<ConvexFace> box = convex_faces(make_box({0, 0, 0}, {1, 2, 3}));
  ASSERT_EQ(box.size(), 6U);
  for (const ConvexFace& face : box) EXPECT_EQ(face.corners.size(), 4U);
}

}  // namespace
}  // namespace skylit
