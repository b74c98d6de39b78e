// The obstacles' sky-light patches (render/obstacle_sky_light.h): where a patch's value
// is computed, which hits share it, and that they belong to planes, not triangles.
#include "skylit/render/obstacle_sky_light.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>

#include "skylit/geometry/plane_groups.h"
#include "skylit/geometry/primitives.h"

namespace skylit {
namespace {

// A ground plane 200 m across, and an integral that returns where it was asked (x, y
// and the normal's z in the first three bins) and counts its calls.
struct Ground {
  Scene scene;
  RayTracer tracer;
  std::atomic<int> calls{0};
  ObstacleSkyLight patches;
  Ground()
      : scene(make_scene()),
        patches(scene, tracer, {1024, 256}, [this](int, const Vec3& point, const Vec3& normal, uint64_t) {
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
  // The ground's point at (u, v) in its plane's frame (geometry/plane_groups.h), in which
  // the patches are squares from (0, 0) on.
  Vec3 in_frame(double u, double v) const {
    const PlaneGroups planes(scene.objects[0].mesh);
    const PlaneGroups::Plane& plane = planes.plane(0);
    return plane.origin + u * plane.e1 + v * plane.e2;
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

TEST(ObstacleSkyLight, HitsOnOnePatchShareOneValueFromAPointOfIt) {
  Ground g;
  // From 2 m the element is 0.22 m wide: the smallest patch, 0.5 m.
  const double side = ObstacleSkyLight::kMinPatchM;
  const Vec3 p = g.in_frame(20.1, 10.1), q = g.in_frame(20.4, 10.3), centre = g.in_frame(20.25, 10.25);
  const Irradiance a = g.seen_from(p.x, p.y, 2), b = g.seen_from(q.x, q.y, 2);
  EXPECT_EQ(g.calls.load(), 1);
  EXPECT_EQ(a.spectrum()[0], b.spectrum()[0]);
  EXPECT_EQ(a.spectrum()[1], b.spectrum()[1]);
  // The value is that of a point of the patch's jittered lattice (drawn from the patch,
  // and 1 mm toward its triangle's middle), within its square, on the side met (the
  // normal up).
  EXPECT_LE(std::abs(a.spectrum()[0] - centre.x), side / 2 + 2e-3);
  EXPECT_LE(std::abs(a.spectrum()[1] - centre.y), side / 2 + 2e-3);
  EXPECT_FLOAT_EQ(a.spectrum()[2], 1.0f);
  // A hit a patch away has its own.
  const Vec3 next = g.in_frame(20.1 + side, 10.1);
  g.seen_from(next.x, next.y, 2);
  EXPECT_EQ(g.calls.load(), 2);
  // Seen again: no new integral.
  const Vec3 again = g.in_frame(20.2, 10.2);
  g.seen_from(again.x, again.y, 2);
  EXPECT_EQ(g.calls.load(), 2);
  // From below, the other side: its own patch, its normal down.
  const Ray up{{p.x, p.y, -2}, {0, 0, 1}};
  const Irradiance below = g.patches.at(0, up, *g.tracer.intersect(up)).value().sky;
  EXPECT_EQ(g.calls.load(), 3);
  EXPECT_FLOAT_EQ(below.spectrum()[2], -1.0f);
}

// A patch's sunlit share: of its 4 × 4 jittered lattice's points (one in each quarter-
// patch cell), asked once per patch, with a ring around it telling whether a shadow edge
// passes within half a patch. Against a shadow edge along y through the 0.5 m patch's
// centre (a cell boundary: half lit whatever the jitter), well before it (all lit) and
// past it (none); and 0.05 m past its side, where the patch is unlit but an element
// reaching over the edge takes its footprint's share from the sun map.
TEST(ObstacleSkyLight, APatchsSunlitShareIsThePartOfItTheSunReaches) {
  Ground g;
  const Vec3 p = g.in_frame(20.1, 10.1);
  const double cx = g.in_frame(20.25, 10.25).x;  // the centre of the patch of the test above
  const Ray ray{{p.x, p.y, 2}, {0, 0, -1}};
  struct Case {
    double edge_x;
    float share;
    bool edge_near;
  };
  for (const Case& c :
       {Case{cx, 0.5f, true}, Case{cx - 1.0, 1.0f, false}, Case{cx + 1.0, 0.0f, false}, Case{cx + 0.3, 0.0f, true}}) {
    int asked = 0;
    const ObstacleSkyLight patches(
        g.scene, g.tracer, {1024}, [](int, const Vec3&, const Vec3&, uint64_t) { return Irradiance(1.0f); },
        [&](const Vec3& point, const Vec3& normal) {
          ++asked;
          EXPECT_FLOAT_EQ(static_cast<float>(normal.z), 1.0f);
          return point.x > c.edge_x;
        });
    int asked_once = -1;
    for (int repeat = 0; repeat < 3; ++repeat) {
      const std::optional<ObstacleSkyLight::Patch> patch = patches.at(0, ray, *g.tracer.intersect(ray));
      ASSERT_TRUE(patch.has_value());
      EXPECT_FLOAT_EQ(patch->sunlit, c.share) << c.edge_x - cx;
      EXPECT_EQ(patch->on_plane != 0, c.edge_near) << c.edge_x - cx;
      if (asked_once < 0) asked_once = asked;
    }
    EXPECT_EQ(asked, asked_once);  // once per patch
    // Without an edge near, the 16 points and the ring's 12: the map is not kept.
    if (!c.edge_near) {
      EXPECT_EQ(asked, 28);
    }
  }
  // The element seen from 2 m straight down at 0.2 m past the centre, 0.2 rad wide: its
  // footprint runs from the centre to 0.4 m past it, a quarter of it past the edge at
  // 0.3 m; the map's cells are an eighth of a metre, so within one cell's share of the
  // footprint's 0.4 m (about 0.3).
  const ObstacleSkyLight patches(
      g.scene, g.tracer, {1024}, [](int, const Vec3&, const Vec3&, uint64_t) { return Irradiance(1.0f); },
      [&](const Vec3& point, const Vec3&) { return point.x > cx + 0.3; });
  const Ray element{{cx + 0.2, p.y, 2}, {0, 0, -1}};
  const std::optional<Hit> hit = g.tracer.intersect(element);
  ASSERT_TRUE(hit.has_value());
  EXPECT_FLOAT_EQ(patches.at(0, element, *hit)->sunlit, 0.0f);
  EXPECT_NEAR(patches.at(0, element, *hit, 0, 0.2)->sunlit, 0.25, 0.3125);
  EXPECT_GT(patches.at(0, element, *hit, 0, 0.2)->sunlit, 0.0f);
  // An element wholly before the edge takes none.
  const Ray before{{cx - 0.1, p.y, 2}, {0, 0, -1}};
  EXPECT_FLOAT_EQ(patches.at(0, before, *g.tracer.intersect(before), 0, 0.1)->sunlit, 0.0f);
}

TEST(ObstacleSkyLight, PatchesGrowWithTheDistanceAsTheElements) {
  Ground g;
  // From 100 m an element of 1024 directions spans 11 m: the patch is 16 m, so points
  // 10 m apart inside one 16 m square share it, and its value's point lies in that square,
  // within its diagonal 16√2 m of both.
  const Vec3 p = g.in_frame(1, 1), q = g.in_frame(11, 3.5);
  const Irradiance a = g.seen_from(p.x, p.y, 100), b = g.seen_from(q.x, q.y, 100);
  EXPECT_EQ(g.calls.load(), 1);
  EXPECT_EQ(a.spectrum()[0], b.spectrum()[0]);
  EXPECT_LE(std::hypot(a.spectrum()[0] - p.x, a.spectrum()[1] - p.y), 16 * std::sqrt(2.0) + 1e-3);
  EXPECT_LE(std::hypot(a.spectrum()[0] - q.x, a.spectrum()[1] - q.y), 16 * std::sqrt(2.0) + 1e-3);
  // Level 1 is looked up by integrals of 256 directions: from 100 m, 22 m, a 32 m patch;
  // its own table.
  g.seen_from(p.x, p.y, 100, 1);
  EXPECT_EQ(g.calls.load(), 2);
  EXPECT_EQ(g.patches.patch_counts(), (std::vector<size_t>{1, 1}));
}

TEST(ObstacleSkyLight, NoPatchIsFinerThanWhatTheImageResolvesWhereTheRayStarts) {
  // Seen from 2 m, but from a point where the image resolves only 10 m: a 16 m patch, so
  // points 10 m apart share it.
  Ground g;
  auto seen = [&](double u, double v) {
    const Vec3 p = g.in_frame(u, v);
    const Ray ray{{p.x, p.y, 2}, {0, 0, -1}};
    return g.patches.at(0, ray, *g.tracer.intersect(ray), 10.0).value().sky;
  };
  const Irradiance a = seen(1, 1), b = seen(11, 1.5);
  EXPECT_EQ(g.calls.load(), 1);
  EXPECT_EQ(a.spectrum()[0], b.spectrum()[0]);
}

TEST(ObstacleSkyLight, APatchOverThePlanesEdgeIsEvaluatedOnIt) {
  // Patches of 64 m (from 400 m) along the edges of planes 200 m and 40 m across hang
  // over them: the value's point lies on the plane and in the patch's square (a point of
  // its lattice that is on the plane).
  for (const double size : {200.0, 40.0}) {
    Scene scene = Ground::make_scene();
    scene.objects[0].mesh = make_ground_plane({0, 0, 0}, size);
    RayTracer tracer;
    tracer.add_mesh(scene.objects[0].mesh);
    tracer.commit();
    const PlaneGroups planes(scene.objects[0].mesh);
    const PlaneGroups::Plane& plane = planes.plane(0);
    const ObstacleSkyLight patches(scene, tracer, {1024}, [&](int, const Vec3& point, const Vec3&, uint64_t) {
      Spectrum s(0.0f);
      s[0] = static_cast<float>(point.x);
      s[1] = static_cast<float>(point.y);
      return Irradiance(s);
    });
    const double half = size / 2 - 0.5;
    int found = 0;
    for (const auto& [x, y] : {std::pair{half, half}, {-half, half}, {half, 0.0}, {0.0, -half}}) {
      const Ray ray{{x, y, 400}, {0, 0, -1}};
      const std::optional<ObstacleSkyLight::Patch> patch = patches.at(0, ray, *tracer.intersect(ray));
      // A square over little of the plane may have none of its lattice on it: then no
      // patch (the integral lights the hit as itself).
      if (!patch) continue;
      ++found;
      const Vec3 point{patch->sky.spectrum()[0], patch->sky.spectrum()[1], 0};
      EXPECT_LE(std::abs(point.x), size / 2 + 1e-3) << x << ", " << y;
      EXPECT_LE(std::abs(point.y), size / 2 + 1e-3) << x << ", " << y;
      // In the hit's square of 64 m.
      const Vec3 hit{x, y, 0};
      for (const Vec3& axis : {plane.e1, plane.e2})
        EXPECT_EQ(std::floor(dot(point - plane.origin, axis) / 64), std::floor(dot(hit - plane.origin, axis) / 64))
            << x << ", " << y;
    }
    EXPECT_GE(found, 1) << size;
  }
}

// The same wall cut into triangles two ways (two triangles; strips 0.1 m wide, each far
// smaller than a patch) has the same patches: one plane, one value per square.
TEST(ObstacleSkyLight, AWallCutIntoStripsHasTheSamePatchesAsAWhole) {
  auto wall_of_strips = [](double strip_m) {
    TriangleMesh wall;
    for (double x0 = 0; x0 < 20 - 1e-9; x0 += strip_m) {
      const auto n = static_cast<uint32_t>(wall.vertices.size());
      wall.vertices.insert(wall.vertices.end(), {{x0, 0, 0}, {x0 + strip_m, 0, 0}, {x0 + strip_m, 0, 8}, {x0, 0, 8}});
      wall.triangles.push_back({n, n + 2, n + 1});
      wall.triangles.push_back({n, n + 3, n + 2});
    }
    return wall;
  };
  std::vector<std::vector<float>> seen;
  std::vector<size_t> counts;
  for (const double strip : {20.0, 0.1}) {
    Scene scene = Ground::make_scene();
    scene.objects[0].mesh = wall_of_strips(strip);
    RayTracer tracer;
    tracer.add_mesh(scene.objects[0].mesh);
    tracer.commit();
    const ObstacleSkyLight patches(scene, tracer, {1024}, [](int, const Vec3& point, const Vec3& normal, uint64_t) {
      Spectrum s(0.0f);
      s[0] = static_cast<float>(point.x);
      s[1] = static_cast<float>(point.z);
      s[2] = static_cast<float>(normal.y);
      return Irradiance(s);
    });
    std::vector<float> values;
    for (double x = 0.35; x < 20; x += 1.7)  // between the strips' edges
      for (double z = 0.25; z < 8; z += 1.3) {
        const Ray ray{{x, -12, z}, {0, 1, 0}};  // from 12 m: 2 m patches
        const std::optional<Hit> hit = tracer.intersect(ray);
        ASSERT_TRUE(hit.has_value());
        const std::optional<ObstacleSkyLight::Patch> patch = patches.at(0, ray, *hit);
        if (!patch) {  // a square over the wall's edge whose points all miss it
          values.insert(values.end(), {-1.0f, -1.0f, -1.0f});
          continue;
        }
        values.insert(values.end(), {patch->sky.spectrum()[0], patch->sky.spectrum()[1], patch->sky.spectrum()[2]});
      }
    counts.push_back(patches.patch_counts()[0]);
    seen.push_back(values);
  }
  EXPECT_EQ(counts[0], counts[1]);
  ASSERT_EQ(seen[0].size(), seen[1].size());
  for (size_t i = 0; i < seen[0].size(); ++i) EXPECT_NEAR(seen[0][i], seen[1][i], 2e-3f) << i;
}

TEST(ObstacleSkyLight, SmallTrianglesAndThePastTheLastLevelHaveNoPatch) {
  // The 200 m plane has 40,000 m²: from 400 m (a 64 m patch) still its own. A box top of
  // 0.5 m² has its own from 1 m (a 0.5 m patch, a quarter of it 0.0625 m²) but not from
  // 20 m (a 4 m patch).
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
  const ObstacleSkyLight small(scene, tracer, {1024}, [&](int, const Vec3&, const Vec3&, uint64_t) {
    ++calls;
    return Irradiance(1.0f);
  });
  const Ray near{{0.5, 0.25, 1.5}, {0, 0, -1}}, distant{{0.5, 0.25, 20.5}, {0, 0, -1}};
  EXPECT_TRUE(small.at(0, near, *tracer.intersect(near)).has_value());
  EXPECT_FALSE(small.at(0, distant, *tracer.intersect(distant)).has_value());
  EXPECT_EQ(calls, 1);
}

// A patch's point and normal come from its key and its plane alone: the hit's normal,
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
  auto record = [&received](int, const Vec3& point, const Vec3& normal, uint64_t) {
    received.push_back(point);
    received.push_back(normal);
    return Irradiance(Spectrum(1.0f));
  };
  const Vec3 n = normalize(cross(roof.vertices[1] - roof.vertices[0], roof.vertices[2] - roof.vertices[0]));
  const Vec3 hit_point = (roof.vertices[0] + roof.vertices[1] + roof.vertices[2]) / 3.0;
  const Ray ray{hit_point + 5.0 * n, -n};
  RayTracer tracer;
  tracer.add_mesh(roof);
  tracer.commit();
  for (const double nudge : {0.0, 3e-7, -2e-7}) {  // about single precision's last bits
    const ObstacleSkyLight patches(scene, tracer, {1024, 256}, record);
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
