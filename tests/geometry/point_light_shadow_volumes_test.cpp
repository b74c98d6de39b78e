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

TEST(ShadowVolumes, PointLightHierarchyAgreesWithOcclusionRaysOnTessellatedWalls) {
  // Walls of a street in 1 m × 1.5 m panels (1,536 triangles, as city models and their
  // facades come) and a lamp over the street: pieces of view rays starting anywhere
  // along them agree with occlusion rays sample by sample (the hierarchy's arc, distance
  // and height checks drop no frustum that matters, and the panels merged into one face
  // per wall shadow as the panels do); with a reach of 10 m, pieces wholly within it
  // get the same intervals, and fewer frusta are built.
  std::vector<TriangleMesh> meshes(1);
  TriangleMesh& walls = meshes[0];
  for (const double x : {-6.0, 6.0})
    for (int u = 0; u < 32; ++u)
      for (int k = 0; k < 12; ++k) {
        const auto n = static_cast<uint32_t>(walls.vertices.size());
        const double y0 = u - 16.0, z0 = 1.5 * k;
        walls.vertices.insert(walls.vertices.end(),
                              {{x, y0, z0}, {x, y0 + 1, z0}, {x, y0 + 1, z0 + 1.5}, {x, y0, z0 + 1.5}});
        walls.triangles.push_back({n, n + 1, n + 2});
        walls.triangles.push_back({n, n + 2, n + 3});
      }
  meshes.push_back(make_box_centered({2, 3, 0}, {1, 1, 3}, 20));  // a kiosk on the street
  meshes.push_back(make_box_centered({0, 45, 0}, {2, 2, 3}, 0));  // beyond the reach
  const Vec3 lamp{3, 0.5, 8};
  std::vector<const TriangleMesh*> pointers;
  for (const auto& m : meshes) pointers.push_back(&m);
  const PointLightShadowVolumes volumes(pointers, lamp);
  const PointLightShadowVolumes reached(pointers, lamp, {0, 0, -1}, 180, 10);
  EXPECT_LT(reached.volume_count(), volumes.volume_count());
  EXPECT_LE(volumes.volume_count(), 2U + 5 + 5);  // a face per wall, at most 5 lit per box
  RayTracer tracer;
  for (const auto& m : meshes) tracer.add_mesh(m);
  tracer.commit();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uni(0, 1);
  int boundaries = 0;
  for (int r = 0; r < 24; ++r) {
    const Vec3 origin{30 * uni(rng) - 15, 40 * uni(rng) - 20, 0.2 + 20 * uni(rng)};
    const Vec3 target{16 * uni(rng) - 8, 40 * uni(rng) - 20, 6 * uni(rng)};
    const Ray ray{origin, normalize(target - origin)};
    const double t_min = 20 * uni(rng), t_max = t_min + 5 + 30 * uni(rng);
    const auto lit = volumes.lit_intervals(ray, t_min, t_max);
    boundaries += static_cast<int>(2 * lit.size());
    const SampledLight sampled = sample_light(lit, t_max, 20000, [&](double t) {
      if (t < t_min) return false;  // outside the piece: nothing asked
      const Vec3 p = ray.origin + t * ray.direction;
      const Vec3 to_lamp = lamp - p;
      return !tracer.occluded({p, normalize(to_lamp), 0.0, length(to_lamp)});
    });
    EXPECT_EQ(sampled.disagreements, 0) << "ray " << r;
    // The piece's part within 10 m of the lamp (ends at most 10 m off: distance is
    // convex along it) is shadowed the same by the frusta built within the reach.
    double lo = t_min, hi = t_max;
    while (hi > lo && length(ray.origin + hi * ray.direction - lamp) > 10) hi -= 0.01;
    while (hi > lo && length(ray.origin + lo * ray.direction - lamp) > 10) lo += 0.01;
    if (!(hi > lo)) continue;
    const auto all = volumes.lit_intervals(ray, lo, hi), near = reached.lit_intervals(ray, lo, hi);
    ASSERT_EQ(all.size(), near.size()) << "ray " << r;
    for (size_t i = 0; i < all.size(); ++i) {
      EXPECT_NEAR(all[i].begin, near[i].begin, 1e-9) << "ray " << r;
      EXPECT_NEAR(all[i].end, near[i].end, 1e-9) << "ray " << r;
    }
  }
  EXPECT_GT(boundaries, 40);  // the pieces do cross shadows
}

}  // namespace
}  // namespace skylit
