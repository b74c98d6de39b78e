// The material a ray finds is the one of the triangle it meets, for objects with one
// material and objects with a material per triangle (a model file's own).
#include "skylit/render/prepared_scene.h"

#include <gtest/gtest.h>

#include "skylit/geometry/primitives.h"

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

}  // namespace
}  // namespace skylit
