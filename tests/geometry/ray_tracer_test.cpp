// Ray queries: hit distance and normal against analytic answers, occlusion inside
// and outside the segment, ids, watertight edges, degenerate input, thread safety.
#include "skylit/geometry/ray_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <thread>
#include <vector>

#include "skylit/geometry/primitives.h"

namespace skylit {
namespace {

TEST(RayTracer, HitsBoxAtExpectedDistanceAndNormal) {
  RayTracer tracer;
  const uint32_t id = tracer.add_mesh(make_box({2, -1, -1}, {4, 1, 1}));
  tracer.commit();
  EXPECT_EQ(id, 0u);
  EXPECT_EQ(tracer.triangle_count(), 12u);

  // From the origin east: enters the -x face at x = 2.
  auto hit = tracer.intersect({{0, 0.25, 0.5}, {1, 0, 0}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.0, 1e-6);
  EXPECT_NEAR(hit->geometric_normal.x, -1.0, 1e-7);
  EXPECT_NEAR(hit->geometric_normal.y, 0.0, 1e-7);
  EXPECT_NEAR(hit->geometric_normal.z, 0.0, 1e-7);
  EXPECT_EQ(hit->mesh_id, 0u);
  EXPECT_LT(hit->triangle, 12u);

  // A non-unit direction: t is in units of its length.
  hit = tracer.intersect({{0, 0.25, 0.5}, {4, 0, 0}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 0.5, 1e-6);

  // Straight down on the roof (z = 1) from 11 m up; normal +z. The barycentrics
  // rebuild the hit point from the box's own triangle.
  const TriangleMesh box = make_box({2, -1, -1}, {4, 1, 1});
  hit = tracer.intersect({{3.3, 0.2, 11}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 10.0, 1e-5);
  EXPECT_NEAR(hit->geometric_normal.z, 1.0, 1e-7);
  const auto& tri = box.triangles[hit->triangle];
  const Vec3 p =
      (1 - hit->u - hit->v) * box.vertices[tri[0]] + hit->u * box.vertices[tri[1]] + hit->v * box.vertices[tri[2]];
  EXPECT_NEAR(p.x, 3.3, 1e-5);
  EXPECT_NEAR(p.y, 0.2, 1e-5);
  EXPECT_NEAR(p.z, 1.0, 1e-5);

  // From inside the box the far wall is hit, its normal still outward (not flipped).
  hit = tracer.intersect({{3, 0, 0}, {0, 1, 0}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1.0, 1e-6);
  EXPECT_NEAR(hit->geometric_normal.y, 1.0, 1e-7);

  // Diagonal ray at 45° onto the -x face: t = 2·√2.
  hit = tracer.intersect({{0, -2, 0}, normalize({1, 1, 0})});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2 * std::sqrt(2.0), 1e-6);

  // Pointing away, or stopping short, misses.
  EXPECT_FALSE(tracer.intersect({{0, 0, 0}, {-1, 0, 0}}));
  EXPECT_FALSE(tracer.intersect({{0, 0, 0}, {1, 0, 0}, 0, 1.9}));
}

TEST(RayTracer, OcclusionOnlyWithinTheSegment) {
  RayTracer tracer;
  tracer.add_mesh(make_box({2, -1, -1}, {4, 1, 1}));
  tracer.commit();
  EXPECT_TRUE(tracer.occluded({{0, 0, 0}, {1, 0, 0}}));
  EXPECT_TRUE(tracer.occluded({{0, 0, 0}, {1, 0, 0}, 0, 2.1}));
  EXPECT_FALSE(tracer.occluded({{0, 0, 0}, {1, 0, 0}, 0, 1.9}));    // stops short
  EXPECT_FALSE(tracer.occluded({{0, 0, 0}, {1, 0, 0}, 4.1, 100}));  // starts past it
  EXPECT_FALSE(tracer.occluded({{0, 0, 0}, {-1, 0, 0}}));           // points away
  EXPECT_FALSE(tracer.occluded({{0, 0, 2}, {1, 0, 0}}));            // passes above
  EXPECT_TRUE(tracer.occluded({{3, 0, 5}, {0, 0, -1}, 0, 4.5}));    // down onto the roof
}

TEST(RayTracer, MeshIdsFollowCallOrderIncludingEmptyMeshes) {
  RayTracer tracer;
  EXPECT_EQ(tracer.add_mesh(TriangleMesh{}), 0u);
  EXPECT_EQ(tracer.add_mesh(make_ground_plane({0, 0, 0}, 10)), 1u);
  EXPECT_EQ(tracer.add_mesh(make_box({-1, -1, 0}, {1, 1, 2})), 2u);
  tracer.commit();
  EXPECT_EQ(tracer.mesh_count(), 3u);
  EXPECT_EQ(tracer.triangle_count(), 14u);
  auto hit = tracer.intersect({{0, 0, 10}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->mesh_id, 2u);
  EXPECT_NEAR(hit->t, 8.0, 1e-5);
  hit = tracer.intersect({{3, 3, 10}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->mesh_id, 1u);
  EXPECT_NEAR(hit->geometric_normal.z, 1.0, 1e-7);
}

// A ground of 5 m quads sharing edges and vertices, as tiled terrain or a
// triangulated street would be.
TriangleMesh grid(int n, double cell) {
  TriangleMesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) m.vertices.push_back({i * cell, j * cell, 0});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const uint32_t a = i * (n + 1) + j, b = a + (n + 1), c = b + 1, d = a + 1;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  return m;
}

TEST(RayTracer, RaysThroughSharedEdgesDoNotLeak) {
  // Slanted rays aimed exactly at shared edges and vertices must hit one of the
  // triangles there. Without Embree's robust (watertight) mode some of them slip
  // through (measured: 619 of 6400 such rays on a 40 x 40 grid).
  RayTracer tracer;
  tracer.add_mesh(grid(40, 5));
  tracer.commit();
  const Vec3 dir{0.3, 0.1, -1};
  int leaks = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      for (const Vec3 target : {Vec3{i * 5.0, j * 5.0 + 1.3, 0}, Vec3{i * 5.0, j * 5.0, 0},
                                Vec3{i * 5.0 + 2.5, j * 5.0 + 2.5, 0}, Vec3{i * 5.0 + 1.3, j * 5.0, 0}})
        leaks += !tracer.occluded({target - 0.5 * dir, dir, 0, 1});
  EXPECT_EQ(leaks, 0);
}

TEST(RayTracer, DegenerateTrianglesAreHarmless) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 3, 3}, {0, 1, 4}};  // a line, a point, a real one
  RayTracer tracer;
  tracer.add_mesh(mesh);
  tracer.commit();
  EXPECT_EQ(tracer.triangle_count(), 3u);
  EXPECT_FALSE(tracer.intersect({{1.5, 0, 1}, {0, 0, -1}}));
  EXPECT_FALSE(tracer.intersect({{5, 5, 6}, {0, 0, -1}}));
  const auto hit = tracer.intersect({{0.2, 0.2, 1}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->triangle, 2u);
}

TEST(RayTracer, RejectsBadMeshesAndEarlyQueries) {
  RayTracer tracer;
  TriangleMesh bad;
  bad.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bad.triangles = {{0, 1, 3}};
  EXPECT_THROW(tracer.add_mesh(bad), std::invalid_argument);
  bad.triangles = {{0, 1, 2}};
  bad.vertices[1].x = std::nan("");
  EXPECT_THROW(tracer.add_mesh(bad), std::invalid_argument);
  bad.vertices[1].x = 1e39;  // overflows float
  EXPECT_THROW(tracer.add_mesh(bad), std::invalid_argument);
  EXPECT_THROW(tracer.intersect({{0, 0, 0}, {1, 0, 0}}), std::logic_error);
  EXPECT_THROW(tracer.occluded({{0, 0, 0}, {1, 0, 0}}), std::logic_error);
  // After commit, a non-finite ray is a miss rather than undefined behaviour.
  tracer.add_mesh(make_ground_plane({0, 0, 0}, 2));
  tracer.commit();
  EXPECT_EQ(tracer.add_mesh(TriangleMesh{}), 1u);  // rejected meshes took no id
  EXPECT_FALSE(tracer.intersect({{0, 0, 1}, {0, 0, std::nan("")}}));
  EXPECT_FALSE(tracer.occluded({{0, 0, 1}, {0, 0, -1}, 2, 1}));
}

TEST(RayTracer, ConcurrentQueriesAgree) {
  RayTracer tracer;
  for (int i = 0; i < 20; ++i) tracer.add_mesh(make_box_centered({i * 3.0, 0, 5}, {2, 2, 10}, i * 7.0));
  tracer.commit();
  const auto trace_all = [&](std::vector<double>& out) {
    for (int k = 0; k < 2000; ++k) {
      const double x = k * 0.03 - 2;
      const auto hit = tracer.intersect({{x, -10, 3}, {0, 1, 0.01}});
      out.push_back(hit ? hit->t : -1);
    }
  };
  std::vector<double> serial, a, b;
  trace_all(serial);
  std::thread ta([&] { trace_all(a); }), tb([&] { trace_all(b); });
  ta.join();
  tb.join();
  EXPECT_EQ(a, serial);
  EXPECT_EQ(b, serial);
  EXPECT_GT(std::count_if(serial.begin(), serial.end(), [](double t) { return t > 0; }), 100);
}

TEST(RayTracer, PacketsFindWhatSingleRaysFind) {
  // Rays from one point of a street of turned boxes toward a spiral of directions over
  // the sphere (as a surface point's sky rays are), plus rays that must miss: a
  // non-finite one, an empty segment, and a count that is no multiple of the packet.
  RayTracer tracer;
  for (int i = 0; i < 20; ++i) tracer.add_mesh(make_box_centered({i * 3.0, 4, 5}, {2, 2, 10}, i * 7.0));
  tracer.add_mesh(make_ground_plane({0, 0, 0}, 200));
  tracer.commit();
  std::vector<Ray> rays;
  constexpr int kDirections = 1001;
  for (int k = 0; k < kDirections; ++k) {
    const double z = 1 - (2 * k + 1.0) / kDirections, r = std::sqrt(1 - z * z), phi = 2.399963 * k;
    rays.push_back({{25, 0, 1.5}, {r * std::cos(phi), r * std::sin(phi), z}});
  }
  rays.push_back({{25, 0, 1.5}, {0, 0, std::nan("")}});
  rays.push_back({{25, 0, 1.5}, {0, 0, -1}, 2, 1});
  std::vector<std::optional<Hit>> hits;
  tracer.intersect(rays, hits);
  ASSERT_EQ(hits.size(), rays.size());
  int hit_count = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const std::optional<Hit> single = tracer.intersect(rays[i]);
    ASSERT_EQ(hits[i].has_value(), single.has_value()) << "ray " << i;
    if (!single) continue;
    ++hit_count;
    // The same triangle at the same distance: both trace in single precision.
    EXPECT_EQ(hits[i]->mesh_id, single->mesh_id) << "ray " << i;
    EXPECT_EQ(hits[i]->triangle, single->triangle) << "ray " << i;
    EXPECT_NEAR(hits[i]->t, single->t, 1e-5 * single->t) << "ray " << i;
    EXPECT_NEAR(hits[i]->u, single->u, 1e-5) << "ray " << i;
    EXPECT_NEAR(hits[i]->v, single->v, 1e-5) << "ray " << i;
    EXPECT_NEAR(dot(hits[i]->geometric_normal, single->geometric_normal), 1.0, 1e-9) << "ray " << i;
  }
  // Half the directions look down at the ground; some of the rest meet the boxes.
  EXPECT_GT(hit_count, kDirections / 2 + 20);
  EXPECT_LT(hit_count, kDirections);
}

}  // namespace
}  // namespace skylit
