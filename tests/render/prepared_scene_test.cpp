// The material a ray finds is the one of the triangle it meets, for objects with one
// material and objects with a material per triangle (a model file's own).
#include "skylit/render/prepared_scene.h"

#include <gtest/gtest.h>

#include "skylit/geometry/primitives.h"
#include "skylit/geometry/vertex_normals.h"

#include <cmath>

namespace skylit {
namespace {

TEST(PreparedScene, SurfacePointTakesTheMaterialOfTheTriangleHit) {
  Scene scene;
  scene.camera = Camera{{0, -40, 10}, {0, 0, 5}, {0, 0, 1}, 50.0};
  for (const char* name : {"ground", "brick", "glass"})
    scene.materials.push_back({name, DiffuseMaterial{Spectrum(0.5f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 400), 0});
  SceneObject house{"house", make_box({-5, -5, 0}, {5, 5, 10}), 0};
  for (size_t t = 0; t < house.mesh.triangles.size(); ++t) house.triangle_materials.push_back(t % 3 == 0 ? 2 : 1);
  scene.objects.push_back(house);
  const PreparedScene prepared(scene);

  // Aim at each triangle's centroid from outside, along its outward normal.
  for (uint32_t t = 0; t < house.mesh.triangles.size(); ++t) {
    const auto& tri = house.mesh.triangles[t];
    const Vec3 a = house.mesh.vertices[tri[0]], b = house.mesh.vertices[tri[1]], c = house.mesh.vertices[tri[2]];
    const Vec3 centroid = (a + b + c) / 3.0;
    const Vec3 outward = normalize(cross(b - a, c - a));
    if (outward.z < -0.5) continue;  // the floor lies on the ground
    const Ray ray{centroid + 3.0 * outward, -outward};
    const auto hit = prepared.tracer().intersect(ray);
    ASSERT_TRUE(hit);
    ASSERT_EQ(hit->mesh_id, 1u);
    ASSERT_EQ(hit->triangle, t);
    EXPECT_EQ(prepared.surface_point(ray, *hit).material, t % 3 == 0 ? 2u : 1u) << "triangle " << t;
  }
  const Ray down{{100, 100, 5}, {0, 0, -1}};
  EXPECT_EQ(prepared.surface_point(down, *prepared.tracer().intersect(down)).material, 0u);
}

// On a smooth-shaded mesh the normal is the interpolation of the corner normals,
// facing the viewer, and the point is lifted off the flat facet.
TEST(PreparedScene, SmoothMeshesShadeWithInterpolatedNormals) {
  Scene scene;
  scene.camera = Camera{{0, -40, 10}, {0, 0, 5}, {0, 0, 1}, 50.0};
  scene.materials.push_back({"white", DiffuseMaterial{Spectrum(0.5f)}});
  SceneObject drum{"drum", TriangleMesh{}, 0};
  constexpr int kSides = 8;  // facets 45° apart
  for (int k = 0; k < kSides; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / kSides;
    drum.mesh.vertices.push_back({10 * std::cos(a), 10 * std::sin(a), 0});
    drum.mesh.vertices.push_back({10 * std::cos(a), 10 * std::sin(a), 20});
  }
  for (uint32_t k = 0; k < kSides; ++k) {
    const uint32_t next = (k + 1) % kSides;
    drum.mesh.triangles.push_back({2 * k, 2 * next, 2 * next + 1});
    drum.mesh.triangles.push_back({2 * k, 2 * next + 1, 2 * k + 1});
  }
  drum.corner_normals = crease_angle_normals(drum.mesh, 60);
  scene.objects.push_back(drum);
  const PreparedScene prepared(scene);
  // Toward the facet between the vertices at 270° and 315°, a quarter of the way
  // along it: the normal turns a quarter of the 45° from 270° (radial at the corner)
  // toward 315°, i.e. points at azimuth-angle 270° + 11.25° in the x-y plane.
  const double a0 = 3 * 3.14159265358979323846 / 2, a1 = a0 + 3.14159265358979323846 / 4;
  const Vec3 target =
      0.75 * Vec3{10 * std::cos(a0), 10 * std::sin(a0), 5} + 0.25 * Vec3{10 * std::cos(a1), 10 * std::sin(a1), 5};
  const Ray ray{target + Vec3{0, -30, 0}, {0, 1, 0}};
  const auto hit = prepared.tracer().intersect(ray);
  ASSERT_TRUE(hit);
  const SurfacePoint point = prepared.surface_point(ray, *hit);
  // The normalised mean of two unit normals 45° apart weighted 3:1 turns by
  // atan(sin 45° / (3 + cos 45°)) = 10.8° from the first (float normals: 1e-5).
  const double expected =
      a0 + std::atan(std::sin(3.14159265358979323846 / 4) / (3 + std::cos(3.14159265358979323846 / 4)));
  EXPECT_NEAR(point.normal.x, std::cos(expected), 1e-5);
  EXPECT_NEAR(point.normal.y, std::sin(expected), 1e-5);
  EXPECT_NEAR(point.normal.z, 0, 1e-6);
  // Lifted outward from the facet: farther from the axis than the flat hit point.
  const Vec3 flat = ray.origin + hit->t * ray.direction;
  EXPECT_GT(std::hypot(point.position.x, point.position.y), std::hypot(flat.x, flat.y) + 0.05);
}

}  // namespace
}  // namespace skylit
