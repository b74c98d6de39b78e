// Sunlit sections of view rays from shadow volumes (Crow 1977): interval ends behind
// a box against shadow boundaries worked out by hand and by an independent point
// test, a camera standing in shade, unions of shadows, open meshes and a ground
// plane, grazing sun, cracks along shared edges, agreement with Embree occlusion
// sampled along the ray, bad input, threads, and speed.
#include "skylit/geometry/sun_shadow_volumes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <thread>
#include <vector>

#include "shadow_test_support.h"
#include "skylit/geometry/primitives.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/geometry/transform.h"

namespace skylit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTol = 1e-6;  // metres (all test directions are unit)

double total(const std::vector<Interval>& v) {
  double s = 0;
  for (const Interval& i : v) s += i.end - i.begin;
  return s;
}

// The shadowed pieces of [t_min, t_max]: the complement of the sunlit ones.
std::vector<Interval> shadow_pieces(const std::vector<Interval>& lit, double t_min, double t_max) {
  std::vector<Interval> dark;
  double cursor = t_min;
  for (const Interval& i : lit) {
    if (i.begin > cursor) dark.push_back({cursor, i.begin});
    cursor = i.end;
  }
  if (cursor < t_max) dark.push_back({cursor, t_max});
  return dark;
}

// Whether the half-line p + s w, s >= 0, meets the box [lo, hi] (slab test): the
// point p is in the box's shadow. Independent of the code under test.
bool half_line_meets_box(const Vec3& p, const Vec3& w, const Vec3& lo, const Vec3& hi) {
  double s0 = 0, s1 = kInf;
  for (int k = 0; k < 3; ++k) {
    if (w[k] == 0) {
      if (p[k] < lo[k] || p[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - p[k]) / w[k], b = (hi[k] - p[k]) / w[k];
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a);
    s1 = std::min(s1, b);
  }
  return s0 <= s1;
}

// The shadow of a convex body on a ray is one interval (the body swept along -w is
// convex); find it by scanning for a shadowed t, then bisecting both ends.
template <typename InShadow>
std::optional<Interval> bisect_shadow(InShadow in_shadow, double t_min, double t_max) {
  std::optional<double> inside;
  for (int i = 0; i <= 20000 && !inside; ++i) {
    const double t = t_min + (t_max - t_min) * i / 20000;
    if (in_shadow(t)) inside = t;
  }
  if (!inside) return std::nullopt;
  auto edge = [&](double in, double out) {
    for (int k = 0; k < 200; ++k) {
      const double mid = 0.5 * (in + out);
      (in_shadow(mid) ? in : out) = mid;
    }
    return 0.5 * (in + out);
  };
  return Interval{in_shadow(t_min) ? t_min : edge(*inside, t_min), in_shadow(t_max) ? t_max : edge(*inside, t_max)};
}

// A box of the given size centred on c and turned by angle_deg about z (as
// make_box_centered), as an exact shadow predicate along a ray.
auto rotated_box_shadow(const Vec3& c, const Vec3& size, double angle_deg, const Vec3& w, const Ray& ray) {
  const double ca = std::cos(radians(angle_deg)), sa = std::sin(radians(angle_deg));
  auto to_local = [=](const Vec3& v) { return Vec3{ca * v.x + sa * v.y, -sa * v.x + ca * v.y, v.z}; };
  const Vec3 wl = to_local(w), half = 0.5 * size;
  return [=](double t) { return half_line_meets_box(to_local(ray.origin + t * ray.direction - c), wl, -half, half); };
}

// Cube [-1, 1]^3 with each face split into n x n squares of two triangles, every
// triangle with its own three vertices (as glTF exporters write meshes with
// per-face normals). Coordinates come from integers, so shared corners are equal.
TriangleMesh subdivided_cube(int n) {
  TriangleMesh mesh;
  auto coord = [n](int k) { return -1.0 + 2.0 * k / n; };
  // Each face: fixed axis and side, then the two in-face axes ordered so that
  // cross(e1, e2) points outward.
  struct Face {
    int axis, side, a1, a2;
  };
  const Face faces[] = {{0, n, 1, 2}, {0, 0, 2, 1}, {1, n, 2, 0}, {1, 0, 0, 2}, {2, n, 0, 1}, {2, 0, 1, 0}};
  for (const Face& f : faces)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        auto point = [&](int di, int dj) {
          int k[3];
          k[f.axis] = f.side;
          k[f.a1] = i + di;
          k[f.a2] = j + dj;
          return Vec3{coord(k[0]), coord(k[1]), coord(k[2])};
        };
        const Vec3 p00 = point(0, 0), p10 = point(1, 0), p11 = point(1, 1), p01 = point(0, 1);
        // Alternate the diagonal so some vertices are shared by 4 triangles, others by 8.
        const auto base = static_cast<uint32_t>(mesh.vertices.size());
        if ((i + j) % 2 == 0)
          mesh.vertices.insert(mesh.vertices.end(), {p00, p10, p11, p00, p11, p01});
        else
          mesh.vertices.insert(mesh.vertices.end(), {p00, p10, p01, p10, p11, p01});
        mesh.triangles.push_back({base, base + 1, base + 2});
        mesh.triangles.push_back({base + 3, base + 4, base + 5});
      }
  return mesh;
}

TriangleMesh reversed(TriangleMesh mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// Box [0,10] x [0,10] x [0,20]; sun at altitude 30°, azimuth 120° (east-south-east):
// to_sun = (cos30 sin120, cos30 cos120, sin30) = (0.75, -0.4330, 0.5). Ray along +x
// at height z0, y0 = 15 (5 m north of the box), from x = -50. The point (x, 15, z0)
// is in shadow iff x + 0.75 s in [0, 10], 15 - 0.4330 s in [0, 10] and
// z0 + 0.5 s in [0, 20] for some s >= 0. The y slab gives s in [5, 15] / 0.4330;
// the roof limits s <= (20 - z0) / 0.5; and t = x + 50 then runs from
// 50 - 0.75 s_max to 60 - 0.75 s_min.
TEST(ShadowVolumes, BoxShadowEndpointsMatchHandGeometry) {
  const Vec3 w = direction_from_altitude_azimuth(30, 120);
  const SunShadowVolumes volumes({make_box({0, 0, 0}, {10, 10, 20})}, w);
  const double wy = -w.y;  // 0.4330..., northward reach per unit of s
  ASSERT_NEAR(wy, 0.4330127, 1e-7);

  // Low ray (z0 = 1): the y slab limits both ends.
  {
    const double s_min = 5 / wy, s_max = 15 / wy;
    const double begin = 50 - w.x * s_max, end = 60 - w.x * s_min;  // 24.019, 51.340
    const auto lit = volumes.sunlit_intervals({{-50, 15, 1}, {1, 0, 0}}, 0, 100);
    ASSERT_EQ(lit.size(), 2u);
    EXPECT_NEAR(lit[0].begin, 0, kTol);
    EXPECT_NEAR(lit[0].end, begin, kTol);
    EXPECT_NEAR(lit[1].begin, end, kTol);
    EXPECT_NEAR(lit[1].end, 100, kTol);
    EXPECT_NEAR(begin, 24.0192, 1e-4);
    EXPECT_NEAR(end, 51.3397, 1e-4);
  }
  // Higher ray (z0 = 10): the roof edge cuts the far end of s, so the shadow starts later.
  {
    const double s_min = 5 / wy, s_max = (20 - 10) / w.z;
    const double begin = 50 - w.x * s_max, end = 60 - w.x * s_min;  // 35, 51.340
    const auto lit = volumes.sunlit_intervals({{-50, 15, 10}, {1, 0, 0}}, 0, 100);
    ASSERT_EQ(lit.size(), 2u);
    EXPECT_NEAR(lit[0].end, begin, kTol);
    EXPECT_NEAR(lit[1].begin, end, kTol);
    EXPECT_NEAR(begin, 35.0, 1e-9);
  }
  // Above the shadow's reach at this distance (z0 = 15 needs s <= 10 < 11.55): all sunlit.
  {
    const auto lit = volumes.sunlit_intervals({{-50, 15, 15}, {1, 0, 0}}, 0, 100);
    ASSERT_EQ(lit.size(), 1u);
    EXPECT_EQ(lit[0].begin, 0);
    EXPECT_EQ(lit[0].end, 100);
  }
  // Same answer through the Ray's own t range and through sunlit_length.
  const Ray ray{{-50, 15, 1}, {1, 0, 0}, 0, 100};
  EXPECT_NEAR(total(volumes.sunlit_intervals(ray)), 100 - (60 - 50) - 0.75 * 10 / wy, kTol);
  EXPECT_NEAR(volumes.sunlit_length(ray, 0, 100), total(volumes.sunlit_intervals(ray)), 1e-12);
}

// The camera stands 2 m west and 12 m north of the box above, eye at 1.7 m: the half-line
// toward the sun crosses the box for s in [4.62, 16] (y and x slabs), so it is in shade.
// Looking north (+y), the shade ends where the x slab's far end s = 10 / 0.75 = 16
// leaves the y slab: 12 + t - 0.4330 * 16 = 10, t = 16 * 0.4330 - 2 = 4.928.
TEST(ShadowVolumes, CameraStandingInShadeStartsInShadow) {
  const Vec3 w = direction_from_altitude_azimuth(30, 120);
  const SunShadowVolumes volumes({make_box({0, 0, 0}, {10, 10, 20})}, w);
  const Ray look_north{{-2, 12, 1.7}, {0, 1, 0}};
  const double exit = 16 * (-w.y) - 2;
  const auto lit = volumes.sunlit_intervals(look_north, 0, 50);
  ASSERT_EQ(lit.size(), 1u);
  EXPECT_NEAR(lit[0].begin, exit, kTol);
  EXPECT_NEAR(lit[0].end, 50, kTol);
  EXPECT_NEAR(exit, 4.9282, 1e-4);
  // A ray that stays in the building's shade sees no sunlight at all.
  EXPECT_TRUE(volumes.sunlit_intervals(look_north, 0, 4.5).empty());
  EXPECT_TRUE(volumes.sunlit_intervals({{-2, 12, 1.7}, {0, 0, 1}}, 0, 5).empty());  // looking up, still in shade
  EXPECT_EQ(volumes.sunlit_length(look_north, 1, 3), 0.0);
  // The reverse ray enters the shade and stays in it to its end at the camera.
  const auto back = volumes.sunlit_intervals({{-2, 12 + 50, 1.7}, {0, -1, 0}}, 0, 50);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_NEAR(back[0].begin, 0, kTol);
  EXPECT_NEAR(back[0].end, 50 - exit, kTol);
}

TEST(ShadowVolumes, OverlappingShadowsAreUnited) {
  const Vec3 w = direction_from_altitude_azimuth(30, 120);
  const Vec3 a_lo{0, 0, 0}, a_hi{10, 10, 20}, b_lo{5, 8, 0}, b_hi{15, 18, 30};
  const SunShadowVolumes volumes({make_box(a_lo, a_hi), make_box(b_lo, b_hi)}, w);
  const Ray ray{{-60, 12, 1}, {1, 0, 0}};  // 2 m north of A, through B
  const auto ra = bisect_shadow(
      [&](double t) { return half_line_meets_box(ray.origin + t * ray.direction, w, a_lo, a_hi); }, 0, 100);
  const auto rb = bisect_shadow(
      [&](double t) { return half_line_meets_box(ray.origin + t * ray.direction, w, b_lo, b_hi); }, 0, 100);
  ASSERT_TRUE(ra && rb);
  // The two shadows overlap without either containing the other.
  ASSERT_LT(ra->begin, rb->begin);
  ASSERT_LT(rb->begin, ra->end);
  ASSERT_LT(ra->end, rb->end);
  const auto lit = volumes.sunlit_intervals(ray, 0, 100);
  ASSERT_EQ(lit.size(), 2u);
  EXPECT_NEAR(lit[0].end, ra->begin, kTol);
  EXPECT_NEAR(lit[1].begin, rb->end, kTol);

  // Disjoint shadows of two boxes side by side: three sunlit pieces.
  const SunShadowVolumes apart({make_box({0, 0, 0}, {10, 10, 20}), make_box({40, 0, 0}, {50, 10, 20})}, w);
  EXPECT_EQ(apart.sunlit_intervals({{-60, 15, 1}, {1, 0, 0}}, 0, 150).size(), 3u);
}

TEST(ShadowVolumes, RotatedBoxMatchesIndependentPointTest) {
  const Vec3 c{20, -10, 12}, size{16, 6, 24};
  const double angle = 33;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(0, 1);
  int checked = 0;
  for (double altitude : {12.0, 35.0, 71.0}) {
    const Vec3 w = direction_from_altitude_azimuth(altitude, 250);
    const SunShadowVolumes volumes({make_box_centered(c, size, angle)}, w);
    for (int i = 0; i < 40; ++i) {
      // Rays aimed near the shadow: from a point beside the box, across the sweep.
      const Vec3 target = c - (10 + 60 * uni(rng)) * w + Vec3{8 * uni(rng) - 4, 8 * uni(rng) - 4, 0};
      const Vec3 dir = normalize(Vec3{uni(rng) - 0.5, uni(rng) - 0.5, 0.4 * (uni(rng) - 0.5)});
      const Ray ray{target - 60 * dir, dir};
      const auto ref = bisect_shadow(rotated_box_shadow(c, size, angle, w, ray), 0, 120);
      const auto dark = shadow_pieces(volumes.sunlit_intervals(ray, 0, 120), 0, 120);
      if (!ref) {
        EXPECT_TRUE(dark.empty());
        continue;
      }
      ++checked;
      ASSERT_EQ(dark.size(), 1u) << "ray " << i << " altitude " << altitude;
      EXPECT_NEAR(dark[0].begin, ref->begin, kTol);
      EXPECT_NEAR(dark[0].end, ref->end, kTol);
    }
  }
  EXPECT_GT(checked, 60);  // most rays do cross the shadow
}

// A single-sided wall (two triangles, normal +x) in the plane x = 0, y in [0, 10],
// z in [0, 5]. It casts the same shadow whichever side the sun is on and however it is
// wound, like RayTracer::occluded, which has no back-face culling.
TEST(ShadowVolumes, OpenQuadWallCastsShadowWhicheverWayItIsWound) {
  TriangleMesh wall;
  wall.vertices = {{0, 0, 0}, {0, 10, 0}, {0, 10, 5}, {0, 0, 5}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  for (double azimuth : {90.0, 270.0}) {  // sun in the east (facing the normal), then west
    const Vec3 w = direction_from_altitude_azimuth(30, azimuth);
    for (const TriangleMesh& mesh : {wall, reversed(wall)}) {
      const SunShadowVolumes volumes({mesh}, w);
      EXPECT_EQ(volumes.volume_count(), 2u);  // open: every triangle casts
      // 3 m on the side away from the sun, at 1 m: the sun ray climbs 3 tan30 = 1.73 m
      // to the wall, below its top: shaded for y in [0, 10] (w.y is ~1e-17 here).
      const double x = azimuth == 90 ? -3 : 3;
      const auto lit = volumes.sunlit_intervals({{x, -20, 1}, {0, 1, 0}}, 0, 50);
      ASSERT_EQ(lit.size(), 2u);
      EXPECT_NEAR(lit[0].end, 20, kTol);
      EXPECT_NEAR(lit[1].begin, 30, kTol);
      // On the sunny side: no shadow.
      EXPECT_EQ(volumes.sunlit_intervals({{-x, -20, 1}, {0, 1, 0}}, 0, 50).size(), 1u);
      // Too high to be reached: 1 + 1.73 > 5 needs z > 3.27 at 3 m.
      EXPECT_EQ(volumes.sunlit_intervals({{x, -20, 3.5}, {0, 1, 0}}, 0, 50).size(), 1u);
    }
  }
  // A box without a floor is open too: all 10 triangles cast, and its shadow is the box's.
  const Vec3 w = direction_from_altitude_azimuth(30, 120);
  TriangleMesh open_box = make_box({0, 0, 0}, {10, 10, 20});
  open_box.triangles.erase(open_box.triangles.begin() + 8, open_box.triangles.begin() + 10);  // the -z face
  const SunShadowVolumes open({open_box}, w), closed({make_box({0, 0, 0}, {10, 10, 20})}, w);
  EXPECT_EQ(open.volume_count(), 10u);
  for (double z : {1.0, 10.0}) {
    const Ray ray{{-50, 15, z}, {1, 0, 0}};
    const auto a = open.sunlit_intervals(ray, 0, 100), b = closed.sunlit_intervals(ray, 0, 100);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(a[i].begin, b[i].begin, 1e-9);
      EXPECT_NEAR(a[i].end, b[i].end, 1e-9);
    }
  }
}

// A ground plane at z = 0 casts its shadow downward along -to_sun, below itself:
// rays above it are untouched, the part of a ray below it is dark.
TEST(ShadowVolumes, GroundPlaneShadowsOnlyBelowItself) {
  const Vec3 w = direction_from_altitude_azimuth(40, 200);
  for (const TriangleMesh& ground :
       {make_ground_plane({0, 0, 0}, 1000), reversed(make_ground_plane({0, 0, 0}, 1000))}) {
    const SunShadowVolumes volumes({ground}, w);
    const auto above = volumes.sunlit_intervals({{-100, 0, 2}, {1, 0, 0}}, 0, 200);
    ASSERT_EQ(above.size(), 1u);
    EXPECT_EQ(above[0].begin, 0);
    EXPECT_EQ(above[0].end, 200);
    // Running exactly along the ground: the surface itself is lit (the volume is open there).
    EXPECT_EQ(volumes.sunlit_length({{-100, 0, 0}, {1, 0, 0}}, 0, 200), 200);
    // Descending at 45°: lit until it crosses z = 0 at t = 10 sqrt 2, dark below.
    const auto down = volumes.sunlit_intervals({{0, 0, 10}, normalize(Vec3{1, 0, -1})}, 0, 30);
    ASSERT_EQ(down.size(), 1u);
    EXPECT_NEAR(down[0].end, 10 * std::sqrt(2.0), kTol);
    // Below ground looking up: dark until it comes out.
    const auto up = volumes.sunlit_intervals({{0, 0, -3}, {0, 0, 1}}, 0, kInf);
    ASSERT_EQ(up.size(), 1u);
    EXPECT_NEAR(up[0].begin, 3, kTol);
    EXPECT_EQ(up[0].end, kInf);
  }
}

// Sun 0.5° above the southern horizon behind a 10 m box [-5,5] x [-5,5] x [0,10]: the
// shadow of the roof edge reaches 9 / tan 0.5° = 1031 m north at z = 1.
TEST(ShadowVolumes, GrazingSunCastsLongShadowExactly) {
  const TriangleMesh box = make_box({-5, -5, 0}, {5, 5, 10});
  const Vec3 w = direction_from_altitude_azimuth(0.5, 180);  // (0, -cos, sin)
  const SunShadowVolumes volumes({box}, w);
  // Northward along x = 0 at 1 m, from 20 m south of the box: lit to the south wall
  // (y = -5, t = 15), dark through the box and its shadow to y = 5 + 9 cos/sin.
  const Ray north{{0, -20, 1}, {0, 1, 0}};
  const double end = 25 + 9 * (-w.y) / w.z;
  const auto lit = volumes.sunlit_intervals(north, 0, 2020);
  ASSERT_EQ(lit.size(), 2u);
  EXPECT_NEAR(lit[0].end, 15, kTol);
  EXPECT_NEAR(lit[1].begin, end, kTol);
  EXPECT_NEAR(end - 25, 1031.30, 0.01);

  // Sun exactly on the horizon: roofs are edge-on and cast nothing, the walls cast
  // shadows without end (almost: sin 180° is 1.2e-16, so after 4e16 m the shadow
  // has drifted 5 m sideways, off the ray).
  const SunShadowVolumes horizon({box}, direction_from_altitude_azimuth(0, 180));
  const auto flat = horizon.sunlit_intervals(north, 0, 1e9);
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_NEAR(flat[0].end, 15, kTol);
  EXPECT_EQ(horizon.sunlit_length({{0, -20, 10.5}, {0, 1, 0}}, 0, 5000), 5000);  // above the roof
}

// A closed mesh casts with the triangles that face the sun (the same shadow, half the
// work), whether wound outward, inward, or with a vertex copy per triangle.
TEST(ShadowVolumes, ClosedMeshesCastWithTheirSunFacingHalf) {
  const Vec3 w = direction_from_altitude_azimuth(30, 120);  // faces +x, -y, +z see the sun
  const TriangleMesh box = make_box({0, 0, 0}, {10, 10, 20});
  TriangleMesh unwelded;
  for (const auto& t : box.triangles) {
    const auto base = static_cast<uint32_t>(unwelded.vertices.size());
    for (uint32_t i : t) unwelded.vertices.push_back(box.vertices[i]);
    unwelded.triangles.push_back({base, base + 1, base + 2});
  }
  const SunShadowVolumes outward({box}, w), inward({reversed(box)}, w), copies({unwelded}, w);
  EXPECT_EQ(outward.volume_count(), 6u);
  EXPECT_EQ(inward.volume_count(), 6u);
  EXPECT_EQ(copies.volume_count(), 6u);
  // Two boxes appended into one mesh stay closed (each edge once each way).
  TriangleMesh two = box;
  two.append(make_box({30, 0, 0}, {40, 10, 20}));
  EXPECT_EQ(SunShadowVolumes({two}, w).volume_count(), 12u);
  for (const Ray& ray : {Ray{{-50, 15, 1}, {1, 0, 0}}, Ray{{-2, 12, 1.7}, {0, 1, 0}}, Ray{{5, 5, 5}, {0, 1, 0}}}) {
    const auto a = outward.sunlit_intervals(ray, 0, 100);
    for (const SunShadowVolumes* other : {&inward, &copies}) {
      const auto b = other->sunlit_intervals(ray, 0, 100);
      ASSERT_EQ(a.size(), b.size());
      for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(a[i].begin, b[i].begin, 1e-9);
        EXPECT_NEAR(a[i].end, b[i].end, 1e-9);
      }
    }
  }
  // From inside the (outward-wound) box everything is dark until the ray leaves it and
  // its shadow: the interior is inside the sun-facing triangles' prisms.
  EXPECT_EQ(outward.sunlit_length({{5, 5, 5}, {0, 1, 0}}, 0, 4), 0.0);
}

// A convex body's shadow meets any line in one interval, so a crack between the prisms
// of neighbouring triangles would show as a second shadow piece.
TEST(ShadowVolumes, SharedEdgesAndVerticesLeaveNoCracks) {
  // Sun at the zenith over a subdivided cube: rays lying exactly in the planes swept
  // by shared edges, and through shared vertices.
  const TriangleMesh cube =
      transformed(subdivided_cube(8), Transform::translation({4, 4, 6}) * Transform::scale({4, 4, 4}));
  {
    const SunShadowVolumes volumes({cube}, {0, 0, 1});
    EXPECT_EQ(volumes.volume_count(), 128u);      // the roof; walls are edge-on, floor faces away
    for (double y : {0.0, 1.0, 3.0, 4.0, 8.0}) {  // grid lines of the roof, including its edges
      const auto lit = volumes.sunlit_intervals({{-5, y, 1}, {1, 0, 0}}, 0, 18);
      ASSERT_EQ(lit.size(), 2u) << "y = " << y;
      EXPECT_NEAR(lit[0].end, 5, kTol);
      EXPECT_NEAR(lit[1].begin, 13, kTol);
    }
    // Along the diagonal through grid vertices (k, k) (unnormalised direction: t in units of √2 m).
    const auto diag = volumes.sunlit_intervals({{-2, -2, 3}, {1, 1, 0}}, 0, 12);
    ASSERT_EQ(diag.size(), 2u);
    EXPECT_NEAR(diag[0].end, 2, kTol);
    EXPECT_NEAR(diag[1].begin, 10, kTol);
  }
  // Turned cube, oblique sun, random rays across its shadow.
  const TriangleMesh turned =
      transformed(subdivided_cube(6), Transform::translation({0, 0, 8}) * Transform::rotation_xyz_deg({17, 29, 41}) *
                                          Transform::scale({3, 3, 3}));
  const Vec3 w = direction_from_altitude_azimuth(37, 151);
  const SunShadowVolumes volumes({turned}, w);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(-1, 1);
  int crossing = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 target = Vec3{0, 0, 8} - (5 + 10 * (uni(rng) + 1)) * w + 4 * Vec3{uni(rng), uni(rng), uni(rng)};
    const Vec3 dir = normalize(Vec3{uni(rng), uni(rng), uni(rng)});
    const auto dark = shadow_pieces(volumes.sunlit_intervals({target - 30 * dir, dir}, 0, 60), 0, 60);
    ASSERT_LE(dark.size(), 1u) << "ray " << i;
    crossing += static_cast<int>(dark.size());
  }
  EXPECT_GT(crossing, 5000);
  // Rays through points straight below a vertex (along -to_sun) cross the vertex's
  // swept line, where 4 to 8 prisms meet and their intervals are computed from
  // different planes; a few percent of these crack without the merging tolerance.
  // (Below a silhouette vertex the ray only touches the shadow: no piece.)
  int through = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3& corner = turned.vertices[static_cast<size_t>(i) * 7919 % turned.vertices.size()];
    const Vec3 below = corner - (1 + 5 * (uni(rng) + 1)) * w;
    const Vec3 dir = normalize(Vec3{uni(rng), uni(rng), uni(rng)});
    const auto dark = shadow_pieces(volumes.sunlit_intervals({below - 20 * dir, dir}, 0, 40), 0, 40);
    ASSERT_LE(dark.size(), 1u) << "ray " << i;
    through += static_cast<int>(dark.size());
  }
  EXPECT_GT(through, 15000);
}

// Every sampled point is classified by Embree's occlusion test toward the sun; away
// from the interval ends (where single precision and the step blur the answer) the
// two must agree, and the sunlit lengths agree to within a step per boundary.
TEST(ShadowVolumes, AgreesWithBruteForceOcclusionSampling) {
  std::vector<TriangleMesh> meshes{make_ground_plane({0, 0, 0}, 1000)};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int i = 0; i < 20; ++i)
    meshes.push_back(make_box_centered({200 * uni(rng) - 100, 200 * uni(rng) - 100, 0},
                                       {5 + 20 * uni(rng), 5 + 20 * uni(rng), 10 + 60 * uni(rng)}, 90 * uni(rng)));
  TriangleMesh wall;  // open, single-sided
  wall.vertices = {{-30, 40, 0}, {10, 60, 0}, {10, 60, 25}, {-30, 40, 25}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  meshes.push_back(wall);
  const Vec3 w = direction_from_altitude_azimuth(25, 200);
  const SunShadowVolumes volumes(meshes, w);
  RayTracer tracer;
  for (const auto& m : meshes) tracer.add_mesh(m);
  tracer.commit();

  constexpr int kSamples = 100000;
  const double t_max = 200;
  const double step = t_max / kSamples;
  int shadow_boundaries = 0;
  for (int r = 0; r < 16; ++r) {
    const Vec3 origin{200 * uni(rng) - 100, 200 * uni(rng) - 100, 1 + 20 * uni(rng)};
    const double heading = 2 * kPi * uni(rng);
    const Ray ray{origin, normalize(Vec3{std::cos(heading), std::sin(heading), 0.15 * (uni(rng) - 0.6)})};
    const auto lit = volumes.sunlit_intervals(ray, 0, t_max);
    std::vector<double> ends;
    for (const Interval& i : lit) ends.insert(ends.end(), {i.begin, i.end});
    shadow_boundaries += static_cast<int>(ends.size());
    const SampledLight sampled = sample_light(lit, t_max, kSamples, [&](double t) {
      return !tracer.occluded({ray.origin + t * ray.direction, w});
    });
    EXPECT_EQ(sampled.disagreements, 0) << "ray " << r;
    EXPECT_NEAR(total(lit), sampled.lit_samples * step, (ends.size() + 1) * step) << "ray " << r;
  }
  EXPECT_GT(shadow_boundaries, 40);  // the rays do cross shadows
}

TEST(ShadowVolumes, DegenerateInputs) {
  const Vec3 w = direction_from_altitude_azimuth(45, 180);
  EXPECT_THROW(SunShadowVolumes(std::vector<TriangleMesh>{}, Vec3{0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(SunShadowVolumes(std::vector<TriangleMesh>{}, Vec3{0, std::nan(""), 1}), std::invalid_argument);
  TriangleMesh bad;
  bad.vertices = {{0, 0, 0}, {1, 0, 0}};
  bad.triangles = {{0, 1, 2}};
  EXPECT_THROW(SunShadowVolumes({bad}, w), std::invalid_argument);
  bad.vertices.push_back({0, kInf, 0});
  EXPECT_THROW(SunShadowVolumes({bad}, w), std::invalid_argument);

  // No meshes, an empty mesh, zero-area triangles: nothing casts.
  TriangleMesh flat;
  flat.vertices = {{0, 0, 5}, {1, 1, 5}, {2, 2, 5}};
  flat.triangles = {{0, 1, 2}, {0, 0, 1}};
  const SunShadowVolumes none({TriangleMesh{}, flat}, w);
  EXPECT_EQ(none.volume_count(), 0u);
  EXPECT_EQ(none.sunlit_length({{0, 0, 0}, {1, 0, 0}}, 0, 10), 10);
  // The sun's direction is normalised.
  EXPECT_NEAR(SunShadowVolumes(std::vector<TriangleMesh>{}, Vec3{0, 0, 7}).to_sun().z, 1.0, 1e-15);

  const SunShadowVolumes box({make_box({-1, -1, 0}, {1, 1, 2})}, {0, 0, 1});
  // Non-finite rays meet nothing; reversed or NaN ranges give nothing.
  EXPECT_EQ(box.sunlit_length({{0, 0, std::nan("")}, {1, 0, 0}}, 0, 10), 10);
  EXPECT_TRUE(box.sunlit_intervals({{0, 0, -1}, {1, 0, 0}}, 5, 4).empty());
  EXPECT_TRUE(box.sunlit_intervals({{0, 0, -1}, {1, 0, 0}}, 0, std::nan("")).empty());
  // A zero direction is one point for all t: in the shade under the box, in sun beside it.
  EXPECT_TRUE(box.sunlit_intervals({{0, 0, -1}, {0, 0, 0}}, 0, 10).empty());
  EXPECT_EQ(box.sunlit_length({{3, 0, -1}, {0, 0, 0}}, 0, 10), 10);
  // A ray leaving the lit roof upward: sunlit from its start (no sliver of shade).
  const auto up = box.sunlit_intervals({{0.3, 0.2, 2}, {0, 0, 1}}, 0, 10);
  ASSERT_EQ(up.size(), 1u);
  EXPECT_EQ(up[0].begin, 0);
}

TEST(ShadowVolumes, ThreadsGetIdenticalAnswers) {
  std::vector<TriangleMesh> meshes;
  for (int i = 0; i < 10; ++i) meshes.push_back(make_box_centered({15.0 * i, 7.0 * (i % 3), 10}, {8, 6, 20}, 9.0 * i));
  const SunShadowVolumes volumes(meshes, direction_from_altitude_azimuth(28, 140));
  std::vector<Ray> rays;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int i = 0; i < 4000; ++i)
    rays.push_back({{150 * uni(rng) - 20, 60 * uni(rng) - 30, 1 + 10 * uni(rng)},
                    normalize(Vec3{uni(rng) - 0.5, uni(rng) - 0.5, 0.2 * (uni(rng) - 0.5)})});
  std::vector<std::vector<Interval>> serial(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) serial[i] = volumes.sunlit_intervals(rays[i], 0, 200);
  std::vector<std::vector<std::vector<Interval>>> parallel(4, std::vector<std::vector<Interval>>(rays.size()));
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k)
    threads.emplace_back([&, k] {
      std::vector<Interval> scratch;
      for (size_t i = 0; i < rays.size(); ++i) {
        volumes.sunlit_intervals(rays[(i + 997 * k) % rays.size()], 0, 200, scratch);
        parallel[k][(i + 997 * k) % rays.size()] = scratch;
      }
    });
  for (auto& t : threads) t.join();
  for (int k = 0; k < 4; ++k)
    for (size_t i = 0; i < rays.size(); ++i) {
      ASSERT_EQ(parallel[k][i].size(), serial[i].size());
      for (size_t j = 0; j < serial[i].size(); ++j) {
        EXPECT_EQ(parallel[k][i][j].begin, serial[i][j].begin);
        EXPECT_EQ(parallel[k][i][j].end, serial[i][j].end);
      }
    }
}

// Speed on a street of ~50 buildings and a ground plane, view rays from a pedestrian
// camera ending at the first surface (as the renderer will ask). Printed, with a floor
// far below the measured rate so only a gross slowdown fails.
TEST(ShadowVolumes, QueriesPerSecondOnFiftyBoxes) {
  std::vector<TriangleMesh> meshes{make_ground_plane({0, 0, 0}, 2000)};
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      meshes.push_back(make_box_centered({40.0 * i - 120, 40.0 * j - 120, 0},
                                         {10 + 15 * uni(rng), 10 + 15 * uni(rng), 20 + 60 * uni(rng)}, 30 * uni(rng)));
  meshes.push_back(make_box_centered({170, 20, 0}, {20, 20, 150}, 0));  // a tower
  const SunShadowVolumes volumes(meshes, direction_from_altitude_azimuth(35, 220));
  RayTracer tracer;
  for (const auto& m : meshes) tracer.add_mesh(m);
  tracer.commit();

  std::vector<Ray> rays;
  // From the south-east corner looking north-west, across the shadows, which point
  // north-east (sun in the south-west).
  const Vec3 eye{140, -140, 1.7};
  while (rays.size() < 100000) {
    const double heading = radians(100 + 70 * uni(rng)), pitch = radians(-5 + 25 * uni(rng));
    Ray ray{eye, {std::cos(pitch) * std::cos(heading), std::cos(pitch) * std::sin(heading), std::sin(pitch)}};
    const auto hit = tracer.intersect(ray);
    ray.t_max = hit ? hit->t : 1000.0;
    rays.push_back(ray);
  }
  std::vector<Interval> scratch;
  double lit = 0, length = 0;
  size_t pieces = 0;
  for (const Ray& ray : rays) length += ray.t_max;
  for (const Ray& ray : rays) {
    volumes.sunlit_intervals(ray, ray.t_min, ray.t_max, scratch);
    pieces += scratch.size();
    for (const Interval& i : scratch) lit += i.end - i.begin;
  }
  // Speed belongs in the benchmark (a timed test fails on any slow or instrumented build).
  std::printf("[ shadow volumes ] %zu prisms; per ray: %.2f sunlit pieces, %.1f of %.1f m lit\n",
              volumes.volume_count(), static_cast<double>(pieces) / rays.size(), lit / rays.size(),
              length / rays.size());
  EXPECT_GT(pieces, rays.size());  // some rays do cross shadows
}

}  // namespace
}  // namespace skylit
