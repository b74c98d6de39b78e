// Crease-angle normals against closed forms: a box keeps its face normals, a
// tessellated cylinder gets the radial direction at its vertices (by symmetry the mean
// of the two facets' normals), and the lifted shadow-ray origin lies between the
// facet and the true cylinder.
#include "skylit/geometry/vertex_normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "skylit/geometry/primitives.h"

namespace skylit {
namespace {

Vec3 vec(const std::array<float, 3>& n) { return {n[0], n[1], n[2]}; }

// The side of a cylinder of radius 1 about z, `sides` facets, height 2, outward,
// vertices shared between facets.
TriangleMesh cylinder(int sides) {
  TriangleMesh mesh;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * std::numbers::pi * k / sides;
    mesh.vertices.push_back({std::cos(a), std::sin(a), 0});
    mesh.vertices.push_back({std::cos(a), std::sin(a), 2});
  }
  for (uint32_t k = 0; k < static_cast<uint32_t>(sides); ++k) {
    const uint32_t next = (k + 1) % sides;
    mesh.triangles.push_back({2 * k, 2 * next, 2 * next + 1});
    mesh.triangles.push_back({2 * k, 2 * next + 1, 2 * k + 1});
  }
  return mesh;
}

TEST(VertexNormals, BoxKeepsItsFaceNormals) {
  const TriangleMesh box = make_box({0, 0, 0}, {3, 2, 1});
  const auto normals = crease_angle_normals(box, 30);
  EXPECT_FALSE(any_smooth_corner(box, normals, 0.01));
  // With a crease angle above 90° the box's corners are smoothed.
  EXPECT_TRUE(any_smooth_corner(box, crease_angle_normals(box, 100), 0.01));
}

TEST(VertexNormals, CylinderVerticesGetTheRadialDirection) {
  const TriangleMesh mesh = cylinder(12);  // facets 30° apart
  const auto normals = crease_angle_normals(mesh, 45);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const Vec3 p = mesh.vertices[mesh.triangles[t][c]];
      const Vec3 radial = normalize({p.x, p.y, 0});
      // float normals: 1e-6.
      EXPECT_NEAR(dot(vec(normals[t][c]), radial), 1.0, 1e-6) << t << " " << c;
    }
  // A crease angle below the 30° between facets keeps them flat.
  EXPECT_FALSE(any_smooth_corner(mesh, crease_angle_normals(mesh, 20), 0.01));
}

TEST(VertexNormals, CornersMeetByPositionNotByVertexIndex) {
  // The same cylinder with every triangle on vertices of its own (as exporters often
  // write them, one copy per face): corners at one place are still smoothed together,
  // to the very same normals (they are summed in the same triangle order).
  const TriangleMesh shared = cylinder(12);
  TriangleMesh separate;
  for (const auto& tri : shared.triangles) {
    const auto first = static_cast<uint32_t>(separate.vertices.size());
    for (uint32_t v : tri) separate.vertices.push_back(shared.vertices[v]);
    separate.triangles.push_back({first, first + 1, first + 2});
  }
  EXPECT_EQ(crease_angle_normals(separate, 45), crease_angle_normals(shared, 45));
}

TEST(VertexNormals, ShadowRayOriginIsLiftedTowardTheCurvedSurface) {
  const TriangleMesh mesh = cylinder(12);
  const auto normals = crease_angle_normals(mesh, 45);
  const auto& tri = mesh.triangles[0];
  const std::array<Vec3, 3> corners{mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]};
  // Mid-facet at the bottom edge: the chord lies cos 15° from the axis; the lifted
  // point is farther out, and the lift is of the order of the sagitta 1 − cos 15°
  // (0.034), not more than twice it.
  const Vec3 p = 0.5 * (corners[0] + corners[1]);
  const Vec3 lifted = shading_point(corners, normals[0], 0.5, 0.0);
  const double chord = std::hypot(p.x, p.y), out = std::hypot(lifted.x, lifted.y);
  EXPECT_NEAR(chord, std::cos(std::numbers::pi / 12), 1e-12);
  EXPECT_GT(out, chord + 0.01);
  EXPECT_LT(out - chord, 2 * (1 - chord));
  // At a vertex nothing moves; on a flat triangle nothing moves.
  const Vec3 at_vertex = shading_point(corners, normals[0], 0.0, 0.0);
  EXPECT_NEAR(length(at_vertex - corners[0]), 0, 1e-12);
  const TriangleMesh flat = make_box({0, 0, 0}, {1, 1, 1});
  const auto flat_normals = crease_angle_normals(flat, 30);
  const auto& f = flat.triangles[0];
  const std::array<Vec3, 3> fc{flat.vertices[f[0]], flat.vertices[f[1]], flat.vertices[f[2]]};
  const Vec3 q = shading_point(fc, flat_normals[0], 0.3, 0.3);
  EXPECT_NEAR(length(q - (0.4 * fc[0] + 0.3 * fc[1] + 0.3 * fc[2])), 0, 1e-7);  // float normals
}

}  // namespace
}  // namespace skylit
