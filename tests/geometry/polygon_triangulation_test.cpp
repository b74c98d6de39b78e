// Ear clipping against the polygon itself: the triangles' areas add up to the
// polygon's (shoelace formula, an independent computation), every triangle turns the
// way the outer ring does, and points well inside each triangle lie inside the polygon
// (even-odd rule over all rings), so no triangle covers a hole or the outside. Area
// equal and nothing outside means the triangles tile the polygon exactly.
#include "skylit/geometry/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "skylit/geometry/ray_tracer.h"

namespace skylit {
namespace {

double shoelace(const std::vector<Point2>& ring) {
  double twice = 0;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    twice += (ring[j].x + ring[i].x) * (ring[i].y - ring[j].y);
  return 0.5 * twice;  // > 0 counter-clockwise
}

double polygon_area(const Polygon2& p) {
  double area = std::abs(shoelace(p.outer));
  for (const auto& h : p.holes) area -= std::abs(shoelace(h));
  return area;
}

bool inside_ring(const std::vector<Point2>& ring, Point2 q) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i].y > q.y) != (ring[j].y > q.y) &&
        q.x < ring[j].x + (q.y - ring[j].y) * (ring[i].x - ring[j].x) / (ring[i].y - ring[j].y))
      in = !in;
  return in;
}

bool inside(const Polygon2& p, Point2 q) {
  if (!inside_ring(p.outer, q)) return false;
  for (const auto& h : p.holes)
    if (inside_ring(h, q)) return false;
  return true;
}

std::vector<Point2> all_points(const Polygon2& p) {
  std::vector<Point2> points = p.outer;
  for (const auto& h : p.holes) points.insert(points.end(), h.begin(), h.end());
  return points;
}

// The checks of the file comment, for any polygon.
void expect_tiles(const Polygon2& polygon, const std::string& label) {
  SCOPED_TRACE(label);
  const std::vector<TriangleIndices> triangles = triangulate_polygon(polygon);
  const std::vector<Point2> points = all_points(polygon);
  const double sense = shoelace(polygon.outer) > 0 ? 1.0 : -1.0;
  double area = 0;
  for (const auto& t : triangles) {
    for (uint32_t i : t) ASSERT_LT(i, points.size());
    const Point2 a = points[t[0]], b = points[t[1]], c = points[t[2]];
    const double signed_area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) * sense;
    EXPECT_GT(signed_area, 0) << "a triangle turns against the outer ring";
    area += signed_area;
    // The centroid and a point near each corner, all strictly inside the triangle.
    const std::array<std::array<double, 3>, 4> weights{
        {{1 / 3.0, 1 / 3.0, 1 / 3.0}, {0.9, 0.05, 0.05}, {0.05, 0.9, 0.05}, {0.05, 0.05, 0.9}}};
    for (const auto& w : weights) {
      const Point2 q{w[0] * a.x + w[1] * b.x + w[2] * c.x, w[0] * a.y + w[1] * b.y + w[2] * c.y};
      EXPECT_TRUE(inside(polygon, q)) << "triangle (" << t[0] << ", " << t[1] << ", " << t[2]
                                      << ") reaches outside the polygon at " << q.x << ", " << q.y;
    }
  }
  // Areas are sums of a few hundred products of O(1..100) numbers: double rounding
  // leaves them equal to ~1e-14 relative, far inside the 1e-9.
  EXPECT_NEAR(area, polygon_area(polygon), 1e-9 * polygon_area(polygon));
}

std::vector<Point2> reversed(std::vector<Point2> ring) {
  std::reverse(ring.begin(), ring.end());
  return ring;
}

std::vector<Point2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A bar along the bottom with `teeth` teeth standing on it.
std::vector<Point2> comb(int teeth) {
  std::vector<Point2> ring{{0, 0}, {2.0 * teeth - 1, 0}};
  for (int k = teeth - 1; k >= 0; --k) {
    const double x0 = 2.0 * k, x1 = x0 + 1;
    ring.push_back({x1, 5});
    ring.push_back({x0, 5});
    if (k > 0) {
      ring.push_back({x0, 1});
      ring.push_back({x0 - 1, 1});
    }
  }
  return ring;
}

TEST(PolygonTriangulation, ConcaveShapes) {
  const std::vector<Point2> l_shape{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}};
  const std::vector<Point2> u_shape{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  expect_tiles({l_shape, {}}, "L");
  expect_tiles({reversed(l_shape), {}}, "L clockwise");
  expect_tiles({u_shape, {}}, "U");
  expect_tiles({reversed(u_shape), {}}, "U clockwise");
  expect_tiles({comb(2), {}}, "comb of 2");
  expect_tiles({comb(12), {}}, "comb of 12");
  expect_tiles({reversed(comb(12)), {}}, "comb of 12 clockwise");
  EXPECT_EQ(triangulate_polygon({l_shape, {}}).size(), 4u);  // n − 2 triangles
  EXPECT_EQ(triangulate_polygon({comb(12), {}}).size(), comb(12).size() - 2);
}

TEST(PolygonTriangulation, PolygonsWithHoles) {
  expect_tiles({rectangle(0, 0, 10, 10), {rectangle(2, 2, 4, 4)}}, "square, one hole");
  expect_tiles({rectangle(0, 0, 10, 10), {reversed(rectangle(2, 2, 4, 4)), rectangle(6, 6, 8, 9)}},
               "square, two holes in either orientation");
  // Holes at the same height, so bridges cross rows of other holes' vertices.
  Polygon2 facade{rectangle(0, 0, 12, 9), {}};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col)
      facade.holes.push_back(rectangle(1 + 3 * col, 1 + 3 * row, 2.5 + 3 * col, 2.8 + 3 * row));
  expect_tiles(facade, "facade with 12 windows");
  facade.outer = reversed(facade.outer);
  expect_tiles(facade, "facade, clockwise");
  // A concave outline with holes in its bar and in its teeth.
  expect_tiles({comb(5), {rectangle(1, 0.2, 7, 0.7), rectangle(0.2, 2, 0.8, 4), rectangle(8.1, 1, 8.9, 4.5)}},
               "comb with holes");
  // A U with a hole in each arm, seen from the bridge's hard side (holes west of reflex vertices).
  expect_tiles({{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}},
                {rectangle(0.3, 1.5, 0.7, 2.5), rectangle(2.3, 1.5, 2.7, 2.5)}},
               "U with holes");
}

// Random star-shaped polygons (deeply concave), half of them with a polygonal hole
// around the centre: 300 of them, each checked as above.
TEST(PolygonTriangulation, RandomStarsWithHoles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(1.0, 10.0), unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 3 + trial % 40;
    Polygon2 star;
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * (k + 0.8 * unit(rng)) / n, r = radius(rng);
      star.outer.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    if (trial % 2 && n >= 8) {  // the star then holds the disc of radius 0.76 (gaps ≤ 81°)
      std::vector<Point2> hole;
      const int m = 3 + trial % 7;
      for (int k = 0; k < m; ++k) {
        const double angle = 2 * std::numbers::pi * k / m + 0.3, r = 0.2 + 0.3 * unit(rng);
        hole.push_back({r * std::cos(angle), r * std::sin(angle)});
      }
      star.holes.push_back(hole);
    }
    expect_tiles(star, "star " + std::to_string(trial));
  }
}

TEST(PolygonTriangulation, BrokenInputEndsWithoutCrashing) {
  // Too few points, a zero-area ring, repeated and collinear points, a bow tie.
  EXPECT_TRUE(triangulate_polygon({{{0, 0}, {1, 0}}, {}}).empty());
  EXPECT_TRUE(triangulate_polygon({{{0, 0}, {1, 0}, {2, 0}}, {}}).empty());
  expect_tiles({{{0, 0}, {1, 0}, {1, 0}, {2, 0}, {2, 2}, {2, 2}, {0, 2}}, {}}, "repeated and collinear points");
  const auto bow_tie = triangulate_polygon({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}});
  EXPECT_LE(bow_tie.size(), 2u);
  // A hole outside the outer ring is ignored rather than bridged across the outside.
  expect_tiles({rectangle(0, 0, 1, 1), {}}, "plain square");
  EXPECT_EQ(triangulate_polygon({rectangle(0, 0, 1, 1), {rectangle(5, 5, 6, 6)}}).size(), 2u);
}

TEST(PolygonTriangulation, InSpaceFacesTheOuterRingsNormal) {
  // An L in the vertical plane x = 500123 (a survey easting), outer ring turning
  // counter-clockwise seen from +x, with a hole.
  const auto lift = [](const std::vector<Point2>& ring) {
    std::vector<Vec3> out;
    for (const Point2& p : ring) out.push_back({500123.0, 4000.0 + p.x, 20.0 + p.y});
    return out;
  };
  const std::vector<Point2> l_shape{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}};
  const std::vector<std::vector<Vec3>> rings{lift(l_shape), lift(rectangle(0.2, 0.2, 0.8, 2.5))};
  const Vec3 n = newell_normal(rings[0]);
  EXPECT_NEAR(n.x, 2 * 6.0, 1e-9);  // twice the L's area, along +x
  EXPECT_NEAR(n.y, 0, 1e-9);
  EXPECT_NEAR(n.z, 0, 1e-9);
  std::vector<Vec3> points = rings[0];
  points.insert(points.end(), rings[1].begin(), rings[1].end());
  double area = 0;
  for (const auto& t : triangulate_polygon_3d(rings)) {
    const Vec3 c = cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
    EXPECT_GT(c.x, 0);
    area += 0.5 * length(c);
  }
  // The survey offset costs digits: 5e5 × 2⁻⁵² ≈ 1e-10 m per coordinate.
  EXPECT_NEAR(area, 6.0 - 0.6 * 2.3, 1e-9 * 6.0);
}

// A wall with window holes, traced: rays straight at it pass exactly where the
// geometry has a window, on a grid that avoids the edges.
TEST(PolygonTriangulation, FacadeRendersItsHolesWhereTheGeometrySays) {
  Polygon2 facade{rectangle(0, 0, 12, 9), {}};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col)
      facade.holes.push_back(rectangle(1 + 3 * col, 1 + 3 * row, 2.5 + 3 * col, 2.8 + 3 * row));
  TriangleMesh wall;
  for (const Point2& p : all_points(facade)) wall.vertices.push_back({p.x, 0, p.y});  // in the plane y = 0
  for (const auto& t : triangulate_polygon(facade)) wall.triangles.push_back(t);
  RayTracer tracer;
  tracer.add_mesh(wall);
  tracer.commit();
  int mismatches = 0, holes_seen = 0;
  for (double x = 0.05; x < 12; x += 0.1)
    for (double z = 0.05; z < 9; z += 0.1) {
      const bool hit = tracer.intersect({{x, -5, z}, {0, 1, 0}}).has_value();
      const bool solid = inside(facade, {x, z});
      mismatches += hit != solid;
      holes_seen += !hit;
    }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(holes_seen, 12 * 150);  // each window is 15 × 18 grid points
}

}  // namespace
}  // namespace skylit
