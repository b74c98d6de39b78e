// A point light's lit sections of view rays from its shadow volumes (frusta): every
// point sample agrees with an occlusion ray toward the lamp.
#include "skylit/geometry/point_light_shadow_volumes.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "shadow_test_support.h"
#include "skylit/geometry/primitives.h"
#include "skylit/geometry/ray_tracer.h"

namespace skylit {
namespace {

TEST(ShadowVolumes, PointLightAgreesWithOcclusionRaysTowardTheLight) {
  // A street lamp among boxes, a thin pole and an open wall: along random view rays,
  // every point sample agrees with an occlusion ray toward the lamp, except within
  // 1 mm of an interval end (the samples' own resolution is 2 mm).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(0, 1);
  std::vector<TriangleMesh> meshes;
  for (int i = 0; i < 8; ++i)
    meshes.push_back(make_box_centered({80 * uni(rng) - 40, 80 * uni(rng) - 40, 0},
                                       {2 + 8 * uni(rng), 2 + 8 * uni(rng), 3 + 15 * uni(rng)}, 90 * uni(rng)));
  meshes.push_back(make_box_centered({0.6, 0, 0}, {0.15, 0.15, 7.5}, 0));  // the pole beside the lamp
  TriangleMesh wall;
  wall.vertices = {{-20, 15, 0}, {5, 25, 0}, {5, 25, 9}, {-20, 15, 9}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  meshes.push_back(wall);
  const Vec3 lamp{0, 0, 8};
  std::vector<const TriangleMesh*> pointers;
  for (const auto& m : meshes) pointers.push_back(&m);
  const PointLightShadowVolumes volumes(pointers, lamp);
  RayTracer tracer;
  for (const auto& m : meshes) tracer.add_mesh(m);
  tracer.commit();

  constexpr int kSamples = 50000;
  const double t_max = 100;
  int boundaries = 0;
  for (int r = 0; r < 16; ++r) {
    const Vec3 origin{100 * uni(rng) - 50, 100 * uni(rng) - 50, 0.5 + 10 * uni(rng)};
    const Vec3 target{20 * uni(rng) - 10, 20 * uni(rng) - 10, 4 * uni(rng)};
    const Ray ray{origin, normalize(target - origin)};
    const auto lit = volumes.lit_intervals(ray, 0, t_max);
    boundaries += static_cast<int>(2 * lit.size());
    const SampledLight sampled = sample_light(lit, t_max, kSamples, [&](double t) {
      const Vec3 p = ray.origin + t * ray.direction;
      const Vec3 to_lamp = lamp - p;
      return !tracer.occluded({p, normalize(to_lamp), 0.0, length(to_lamp)});
    });
    EXPECT_EQ(sampled.disagreements, 0) << "ray " << r;
  }
  EXPECT_GT(boundaries, 40);  // the rays do cross shadows
}

}  // namespace
}  // namespace skylit
