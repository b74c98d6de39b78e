// The obstacles' sky-light patches (render/obstacle_sky_light.h): where a patch's value
// is computed, which hits share it, and the nearest point on a triangle it relies on.
#include "skylit/render/obstacle_sky_light.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>

#include "skylit/geometry/primitives.h"

namespace skylit {
namespace {

TEST(ClosestPointOnTriangle, MatchesABruteForceSearch) {
  // Against the nearest of 200 × 200 barycentric samples: never farther than it, and
  // within the samples' spacing of it.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-3, 3);
  auto point = [&] { return Vec3{coordinate(random), coordinate(random), coordinate(random)}; };
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 v0 = point(), v1 = point(), v2 = point(), p = point();
    const Vec3 nearest = closest_point_on_triangle(p, v0, v1, v2);
    double brute = 1e300;
    constexpr int kSteps = 200;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j) {
        const double u = double(i) / kSteps, v = double(j) / kSteps;
        brute = std::min(brute, length(p - ((1 - u - v) * v0 + u * v1 + v * v2)));
      }
    const double spacing = std::max({length(v1 - v0), length(v2 - v0), length(v2 - v1)}) / kSteps;
    EXPECT_LE(length(p - nearest), brute + 1e-9) << trial;
    EXPECT_GE(length(p - nearest), brute - spacing) << trial;
  }
}

// A ground plane 200 m across, and an integral that returns where it was asked (x, y
// and the normal's z in the first three bins) and counts its calls.
struct Ground {
  Scene scene;
  RayTracer tracer;
  std::atomic<int> calls{0};
  ObstacleSkyLight patches;
  Ground()
      : scene(make_scene()), patches(scene, {1024, 256}, [this](int, const Vec3& point, const Vec3& normal) {
          ++calls;
          Spectrum s(0.0f);
          s[0] = static_cast<float>(point.x);
          s[1] = static_cast<float>(point.y);
          s[2] = static_cast<float>(normal.z);
          return Irradiance(s);
        }) {
    tracer.add_mesh(scene.objects[0].mesh);
    tracer.commit();
  }
  static Scene make_scene() {
    Scene scene;
    scene.materials.push_back({"grey", DiffuseMaterial{Spectrum(0.3f)}});
    scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 200), 0});
    return scene;
  }
  // The value for the ground seen straight down from `height` above (x, y).
  Irradiance seen_from(double x, double y, double height, int level = 0) const {
    const Ray ray{{x, y, height}, {0, 0, -1}};
    const std::optional<Hit> hit = tracer.intersect(ray);
    EXPECT_TRUE(hit.has_value());
    const std::optional<ObstacleSkyLight::Patch> value = patches.at(level, ray, *hit);
    EXPECT_TRUE(value.has_value());
    return value ? value->sky : Irradiance(0.0f);
  }
};

TEST(ObstacleSkyLight, HitsOnOnePatchShareItsValueFromItsCentre) {
  Ground g;
  // From 2 m the element is 0.22 m wide: the smallest patch, 0.5 m. (Below the plane's
  // diagonal y = x, in its triangle whose first edge runs along x: patches square to x.)
  const Irradiance a = g.seen_from(20.1, 10.1, 2), b = g.seen_from(20.4, 10.3, 2);
  EXPECT_EQ(g.calls.load(), 1);
  EXPECT_EQ(a.spectrum()[0], b.spectrum()[0]);
  EXPECT_EQ(a.spectrum()[1], b.spectrum()[1]);
  // The value is the patch's centre's, on the side met (the normal up).
  const double side = ObstacleSkyLight::kMinPatchM;
  EXPECT_LE(std::abs(a.spectrum()[0] - 20.1), side);
  EXPECT_LE(std::abs(a.spectrum()[1] - 10.1), side);
  EXPECT_FLOAT_EQ(a.spectrum()[2], 1.0f);
  // A hit a patch away has its own.
  g.seen_from(20.1 + side, 10.1, 2);
  EXPECT_EQ(g.calls.load(), 2);
  // Seen again: no new integral.
  g.seen_from(20.2, 10.2, 2);
  EXPECT_EQ(g.calls.load(), 2);
  // From below, the other side: its own patch, its normal down.
  const Ray up{{20.1, 10.1, -2}, {0, 0, 1}};
  const Irradiance below = g.patches.at(0, up, *g.tracer.intersect(up)).value().sky;
  EXPECT_EQ(g.calls.load(), 3);
  EXPECT_FLOAT_EQ(below.spectrum()[2], -1.0f);
}

// The sun's share of a patch: the part of it that sees the sun, from points spread over
// it, asked once per patch. Against a shadow edge along y placed through the patch's
// centre (half lit), before it (all lit) and past it (none).
TEST(ObstacleSkyLight, APatchsSunlitShareIsThePartOfItTheSunReaches) {
  Ground g;
  const Irradiance centre = g.seen_from(20.1, 10.1, 2);  // the patch of the test above
  const double cx = centre.spectrum()[0];
  const Ray ray{{20.1, 10.1, 2}, {0, 0, -1}};
  for (const auto& [edge, share] : {std::pair{cx, 0.5f}, std::pair{cx - 1.0, 1.0f}, std::pair{cx + 1.0, 0.0f}}) {
    const double edge_x = edge;  // Clang 14 cannot capture a structured binding in a lambda
    int asked = 0;
    const ObstacleSkyLight patches(
        g.scene, {1024}, [](int, const Vec3&, const Vec3&) { return Irradiance(1.0f); },
        [&](const Vec3& point, const Vec3& normal) {
          ++asked;
          EXPECT_FLOAT_EQ(static_cast<float>(normal.z), 1.0f);
          return point.x > edge_x;
        });
    for (int repeat = 0; repeat < 3; ++repeat) {
      const std::optional<ObstacleSkyLight::Patch> patch = patches.at(0, ray, *g.tracer.intersect(ray));
      ASSERT_TRUE(patch.has_value());
      EXPECT_FLOAT_EQ(patch->sunlit, share) << edge_x - cx;
    }
    EXPECT_EQ(asked, 4);
  }
}

TEST(ObstacleSkyLight, PatchesGrowWithTheDistanceAsTheElements) {
  Ground g;
  // From 100 m an element of 1024 directions spans 11 m: the patch is 16 m, so points
  // 10 m apart inside one 16 m square share it, and its centre is within 8√2 m.
  const Irradiance a = g.seen_from(0, -1, 100), b = g.seen_from(10, 1.5, 100);
  EXPECT_EQ(g.calls.load(), 1);
  EXPECT_EQ(a.spectrum()[0], b.spectrum()[0]);
  EXPECT_LE(std::hypot(a.spectrum()[0] - 0, a.spectrum()[1] + 1), 8 * std::sqrt(2.0) + 1e-3);
  // Level 1 is looked up by integrals of 256 directions: from 100 m, 22 m, a 32 m patch;
  // its own table.
  g.seen_from(0, -1, 100, 1);
  EXPECT_EQ(g.calls.load(), 2);
  EXPECT_EQ(g.patches.patch_counts(), (std::vector<size_t>{1, 1}));
}

TEST(ObstacleSkyLight, NoPatchIsFinerThanWhatTheImageResolvesWhereTheRayStarts) {
  // Seen from 2 m, but from a point where the image resolves only 10 m: a 16 m patch, so
  // points 10 m apart share it.
  Ground g;
  auto seen = [&](double x, double y) {
    const Ray ray{{x, y, 2}, {0, 0, -1}};
    return g.patches.at(0, ray, *g.tracer.intersect(ray), 10.0).value().sky;
  };
  const Irradiance a = seen(0, -1), b = seen(10, -1.5);
  EXPECT_EQ(g.calls.load(), 1);
  EXPECT_EQ(a.spectrum()[0], b.spectrum()[0]);
}

TEST(ObstacleSkyLight, APatchOverATrianglesEdgeIsEvaluatedInsideIt) {
  // A patch of 64 m at the plane's corner hangs over its edge; its value's point is the
  // nearest point of the triangle to the square's centre, within the plane.
  Ground g;
  const Irradiance corner = g.seen_from(99, 99, 400);
  EXPECT_LE(corner.spectrum()[0], 100.0f);
  EXPECT_LE(corner.spectrum()[1], 100.0f);
  EXPECT_GT(corner.spectrum()[0], 99.0f - 64);
}

TEST(ObstacleSkyLight, SmallTrianglesAndThePastTheLastLevelHaveNoPatch) {
  // The 200 m plane's triangles have 20,000 m²: from 400 m (a 64 m patch) still their own.
  // A box top of two 0.25 m² triangles has its own from 1 m (a 0.5 m patch, a quarter of
  // it 0.0625 m²) but
  // not from 20 m (a 4 m patch).
  Ground g;
  const Ray far{{0, -1, 400}, {0, 0, -1}};
  EXPECT_TRUE(g.patches.at(0, far, *g.tracer.intersect(far)).has_value());
  EXPECT_FALSE(g.patches.at(2, far, *g.tracer.intersect(far)).has_value());  // two levels
  Scene scene = Ground::make_scene();
  scene.objects[0].mesh = make_box({0, 0, 0}, {1, 0.5, 0.5});
  RayTracer tracer;
  tracer.add_mesh(scene.objects[0].mesh);
  tracer.commit();
  int calls = 0;
  const ObstacleSkyLight small(scene, {1024}, [&](int, const Vec3&, const Vec3&) {
    ++calls;
    return Irradiance(1.0f);
  });
  const Ray near{{0.5, 0.25, 1.5}, {0, 0, -1}}, distant{{0.5, 0.25, 20.5}, {0, 0, -1}};
  EXPECT_TRUE(small.at(0, near, *tracer.intersect(near)).has_value());
  EXPECT_FALSE(small.at(0, distant, *tracer.intersect(distant)).has_value());
  EXPECT_EQ(calls, 1);
}

// A patch's point and normal come from its key and its triangle alone: the hit's normal,
// which Embree finds in single precision and whose last bits differ between the paths
// that meet a triangle (a packet's lane, a single ray), must not move them, or the first
// ray to meet a patch would decide its value (images differed with the threads' timing).
TEST(ObstacleSkyLight, APatchDoesNotDependOnTheLastBitsOfTheHitsNormal) {
  Scene scene;
  scene.materials.push_back({"grey", DiffuseMaterial{Spectrum(0.3f)}});
  TriangleMesh roof;  // a sloped triangle: every component of its normal is non-zero
  roof.vertices = {{0, 0, 0}, {40, 3, 12}, {5, 40, 7}};
  roof.triangles = {{0, 1, 2}};
  scene.objects.push_back({"roof", roof, 0});
  std::vector<Vec3> received;
  auto record = [&received](int, const Vec3& point, const Vec3& normal) {
    received.push_back(point);
    received.push_back(normal);
    return Irradiance(Spectrum(1.0f));
  };
  const Vec3 n = normalize(cross(roof.vertices[1] - roof.vertices[0], roof.vertices[2] - roof.vertices[0]));
  const Vec3 hit_point = (roof.vertices[0] + roof.vertices[1] + roof.vertices[2]) / 3.0;
  const Ray ray{hit_point + 5.0 * n, -n};
  for (const double nudge : {0.0, 3e-7, -2e-7}) {  // about single precision's last bits
    const ObstacleSkyLight patches(scene, {1024, 256}, record);
    const Vec3 hit_normal = normalize(n + Vec3{nudge, -nudge, 0.5 * nudge});
    ASSERT_TRUE(patches.at(0, ray, Hit{5.0, hit_normal, 0, 0, 0.3f, 0.3f}).has_value());
  }
  ASSERT_EQ(received.size(), 6u);
  for (size_t i = 2; i < received.size(); i += 2) {
    EXPECT_EQ(received[i].x, received[0].x);
    EXPECT_EQ(received[i].y, received[0].y);
    EXPECT_EQ(received[i].z, received[0].z);
    EXPECT_EQ(received[i + 1].x, received[1].x);
    EXPECT_EQ(received[i + 1].y, received[1].y);
    EXPECT_EQ(received[i + 1].z, received[1].z);
  }
  // On the side met: the normal faces the ray's origin.
  EXPECT_GT(dot(received[1], -ray.direction), 0.99);
}

}  // namespace
}  // namespace skylit
