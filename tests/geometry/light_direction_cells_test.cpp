// The cube map of a lamp's directions (light_direction_cells.h) as PointLightShadowVolumes
// uses it: a piece walked cell by cell gets exactly the shadows that clipping every
// frustum gives, and the walk itself visits the cells of the piece's directions in order.
#include "skylit/geometry/light_direction_cells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "skylit/geometry/point_light_shadow_volumes.h"
#include "skylit/geometry/primitives.h"
#include "skylit/geometry/shadow_casters.h"

namespace skylit {
namespace {

// A dense block: rotated boxes, a street of walls in 1 m panels, a pitched roof, a large
// ground and a board 5 cm from the lamp (whose directions span a half sphere), around the
// origin or shifted by survey coordinates.
std::vector<TriangleMesh> dense_block(const Vec3& offset, std::mt19937& rng) {
  std::uniform_real_distribution<double> uni(0, 1);
  std::vector<TriangleMesh> meshes;
  meshes.reserve(64);
  for (int i = 0; i < 60; ++i)
    meshes.push_back(make_box_centered(offset + Vec3{120 * uni(rng) - 60, 120 * uni(rng) - 60, 0},
                                       {1 + 10 * uni(rng), 1 + 10 * uni(rng), 2 + 25 * uni(rng)}, 90 * uni(rng)));
  TriangleMesh walls;
  for (const double x : {-7.0, 7.0})
    for (int u = 0; u < 40; ++u)
      for (int k = 0; k < 8; ++k) {
        const auto n = static_cast<uint32_t>(walls.vertices.size());
        const double y = u - 20.0, z = 1.5 * k;
        walls.vertices.insert(walls.vertices.end(), {offset + Vec3{x, y, z}, offset + Vec3{x, y + 1, z},
                                                     offset + Vec3{x, y + 1, z + 1.5}, offset + Vec3{x, y, z + 1.5}});
        walls.triangles.push_back({n, n + 1, n + 2});
        walls.triangles.push_back({n, n + 2, n + 3});
      }
  meshes.push_back(walls);
  TriangleMesh roof;  // a pitched roof over a shed, open below
  roof.vertices = {offset + Vec3{10, -4, 4}, offset + Vec3{16, -4, 4}, offset + Vec3{16, -4 + 3, 6},
                   offset + Vec3{10, -1, 6}, offset + Vec3{10, 2, 4},  offset + Vec3{16, 2, 4}};
  roof.triangles = {{0, 1, 2}, {0, 2, 3}, {3, 2, 5}, {3, 5, 4}};
  meshes.push_back(roof);
  TriangleMesh ground;
  ground.vertices = {offset + Vec3{-500, -500, 0}, offset + Vec3{500, -500, 0}, offset + Vec3{500, 500, 0},
                     offset + Vec3{-500, 500, 0}};
  ground.triangles = {{0, 1, 2}, {0, 2, 3}};
  meshes.push_back(ground);
  TriangleMesh board;  // just beside the lamp
  board.vertices = {offset + Vec3{1.05, -1, 7}, offset + Vec3{1.05, 1, 7}, offset + Vec3{1.05, 1, 9},
                    offset + Vec3{1.05, -1, 9}};
  board.triangles = {{0, 1, 2}, {0, 2, 3}};
  meshes.push_back(board);
  return meshes;
}

// Length of the parts of [t_min, t_max] lit in one of `a` and `b` but not the other
// (both sorted and disjoint).
double lit_difference(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  double both = 0;
  for (size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    both += std::max(0.0, std::min(a[i].end, b[j].end) - std::max(a[i].begin, b[j].begin));
    (a[i].end < b[j].end ? i : j) += 1;
  }
  return total_length(a) + total_length(b) - 2 * both;
}

// Whether the piece [t_min, t_max] of `ray` gets the same light walked over the cells as
// the ray with no end (every frustum clipped) cut to the piece. The shadow-volume
// queries drop light and shadow shorter than 1e-9 of the coordinates' size as rounding
// (shadow_volume.h), and a shadow running past t_max is a sliver on the piece but not
// on the ray with no end: so the two may differ by twice that, no more. Counts the
// piece's ends of light in `boundaries`.
bool walk_agrees_with_every_frustum(const PointLightShadowVolumes& volumes, const Ray& ray, double t_min, double t_max,
                                    int& boundaries) {
  const std::vector<Interval> walked = volumes.lit_intervals(ray, t_min, t_max);
  std::vector<Interval> every;
  for (const Interval& i : volumes.lit_intervals(ray, t_min, std::numeric_limits<double>::infinity()))
    if (i.begin < t_max) every.push_back({i.begin, std::min(i.end, t_max)});
  boundaries += static_cast<int>(2 * walked.size());
  return lit_difference(walked, every) <= 2e-9 * std::max(100.0, max_abs(ray.origin));
}

TEST(LightDirectionCells, PiecesGetTheShadowsOfEveryFrustum) {
  // Pieces of view rays, bounded (walked over the cells) against the same rays with no
  // end (every frustum clipped), cut to the piece: the same lit intervals to 1e-9 m, for
  // lamps in the street, over a roof, at a wall's foot and 5 cm from a board, near the
  // origin and 300 km from it.
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> uni(0, 1);
  int compared = 0, boundaries = 0;
  for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{3e5, 5.8e6, 40}}) {
    const std::vector<TriangleMesh> meshes = dense_block(offset, rng);
    std::vector<const TriangleMesh*> pointers;
    pointers.reserve(meshes.size());
    for (const auto& m : meshes) pointers.push_back(&m);
    for (const Vec3 lamp : {Vec3{0, 0, 8}, Vec3{13, -1, 7.5}, Vec3{6.9, 3, 0.3}, Vec3{1, 0, 8}}) {
      const PointLightShadowVolumes volumes(pointers, offset + lamp);
      for (int r = 0; r < 360; ++r) {
        Vec3 origin = offset + Vec3{160 * uni(rng) - 80, 160 * uni(rng) - 80, 0.2 + 30 * uni(rng)};
        // A third of the rays aimed near the lamp, where the directions turn fastest; a
        // third random; a third in a plane through the lamp and a cube axis (a horizontal
        // ray at the lamp's height, say), where one of a cube face's coordinates stays put.
        Vec3 target = r % 3 == 0 ? offset + lamp + Vec3{uni(rng) - 0.5, uni(rng) - 0.5, uni(rng) - 0.5}
                                 : offset + Vec3{60 * uni(rng) - 30, 60 * uni(rng) - 30, 10 * uni(rng)};
        if (r % 3 == 2) {
          const int axis = (r / 3) % 3;
          origin[axis] = offset[axis] + lamp[axis];
          target[axis] = origin[axis];
        }
        const Ray ray{origin, normalize(target - origin)};
        const double t_min = 40 * uni(rng), t_max = t_min + 1 + 150 * uni(rng);  // longer than rounding
        EXPECT_TRUE(walk_agrees_with_every_frustum(volumes, ray, t_min, t_max, boundaries))
            << "offset " << offset.x << " lamp " << lamp.x << " ray " << r;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 2880);
  EXPECT_GT(boundaries, 2000);  // the pieces do cross shadows
}

TEST(LightDirectionCells, PiecesInAPlaneThroughTheLampAndACubeAxis) {
  // In a plane through the lamp and a cube axis (a horizontal ray at the lamp's height)
  // one coordinate of a cube face stays put along the piece, and the cells' edges ahead
  // along it have no crossing but a spurious one behind: small boards around the lamp at
  // its height, near the origin and 300 km from it, against every frustum.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(0, 1);
  int boundaries = 0;
  for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{3e5, 5.8e6, 40}}) {
    const Vec3 lamp = offset + Vec3{0.3, -0.7, 5.25};
    std::vector<TriangleMesh> meshes;
    meshes.reserve(80);
    for (int i = 0; i < 80; ++i)
      meshes.push_back(make_box_centered(offset + Vec3{60 * uni(rng) - 30, 60 * uni(rng) - 30, 4 + 2 * uni(rng)},
                                         {0.2 + uni(rng), 0.2 + uni(rng), 0.5 + uni(rng)}, 90 * uni(rng)));
    std::vector<const TriangleMesh*> pointers;
    pointers.reserve(meshes.size());
    for (const auto& m : meshes) pointers.push_back(&m);
    const PointLightShadowVolumes volumes(pointers, lamp);
    for (int r = 0; r < 1500; ++r) {
      Vec3 o = offset + Vec3{80 * uni(rng) - 40, 80 * uni(rng) - 40, 2 + 8 * uni(rng)};
      Vec3 d{uni(rng) - 0.5, uni(rng) - 0.5, 0.2 * (uni(rng) - 0.5)};
      const int axis = r % 3;
      o[axis] = lamp[axis];
      d[axis] = 0;
      const double t_min = 40 * uni(rng), t_max = t_min + 1 + 80 * uni(rng);  // longer than rounding
      EXPECT_TRUE(walk_agrees_with_every_frustum(volumes, Ray{o, normalize(d)}, t_min, t_max, boundaries))
          << "offset " << offset.x << " ray " << r;
    }
  }
  EXPECT_GT(boundaries, 1000);  // the pieces do cross shadows
}

TEST(LightDirectionCells, TheWalkVisitsTheCellsOfThePiecesDirectionsInOrder) {
  // One small face in every cell of the cube map (a sphere of facets around the light):
  // a piece's walk returns consecutive parts covering it exactly, and each part's
  // middle lies within its cell's radius of the cell's facet.
  const Vec3 light{2, -3, 5};
  constexpr int kSide = 8;
  LightDirectionCells cells(light, kSide);
  std::vector<Vec3> facet_directions;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i) {
        const int axis = f / 2;
        const double sign = f % 2 == 0 ? 1.0 : -1.0;
        Vec3 centre{0, 0, 0};
        centre[axis] = sign;
        centre[(axis + 1) % 3] = 2.0 * (i + 0.5) / kSide - 1.0;
        centre[(axis + 2) % 3] = 2.0 * (j + 0.5) / kSide - 1.0;
        const Vec3 w = normalize(centre);
        // A tiny square facing the light, 10 m away, well inside its cell.
        const auto [a, b] = perpendicular_pair(w);
        ConvexFace face{{light + 10 * w - 0.01 * a - 0.01 * b, light + 10 * w + 0.01 * a - 0.01 * b,
                         light + 10 * w + 0.01 * a + 0.01 * b, light + 10 * w - 0.01 * a + 0.01 * b},
                        -w};
        cells.add(static_cast<uint32_t>(facet_directions.size()), face);
        facet_directions.push_back(w);
      }
  cells.finish();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(-1, 1);
  int parts = 0;
  for (int r = 0; r < 200; ++r) {
    const Vec3 origin = light + Vec3{20 * uni(rng), 20 * uni(rng), 20 * uni(rng)};
    const Vec3 dir = normalize(Vec3{uni(rng), uni(rng), uni(rng)});
    const double t_min = 5 * uni(rng), t_max = t_min + 40;
    double covered_to = t_min;
    cells.walk(origin, dir, t_min, t_max, [&](const LightDirectionCells::Cell& cell, double t_a, double t_b) {
      EXPECT_NEAR(t_a, covered_to, 1e-9) << "ray " << r;
      EXPECT_LE(t_a, t_b + 1e-12) << "ray " << r;
      covered_to = t_b;
      ASSERT_EQ(cell.end - cell.begin, 1U) << "ray " << r;
      // The part's middle lies within the cell's radius of the direction of its facet.
      const Vec3 middle = normalize(origin + dir * (0.5 * (t_a + t_b)) - light);
      const uint32_t listed = cells.items()[cell.begin];
      EXPECT_GT(dot(facet_directions[listed], middle), std::cos(1.01 * std::sqrt(2.0) / kSide)) << "ray " << r;
      ++parts;
    });
    EXPECT_NEAR(covered_to, t_max, 1e-9) << "ray " << r;
  }
  EXPECT_GT(parts, 1000);  // the pieces do cross many cells
}

}  // namespace
}  // namespace skylit
