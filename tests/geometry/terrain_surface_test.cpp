// Terrain heights and buildings set down on the terrain, with terrain from a CityGML
// TIN relief (read by the CityGML reader) in a projected CRS. The test's stand-in for
// the placement subtracts an origin: over 120 m a projected CRS's scale (0.9996) and
// grid convergence change no height, which is all that is checked here.
#include "skylit/geometry/terrain_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "skylit/io/city/citygml_reader.h"

namespace skylit {
namespace {

constexpr double kEast0 = 380000, kNorth0 = 3940000;  // UTM 54N origin of the stand-in frame

// A CityGML file with a TIN relief over [-60, 60]² m of cells `step` wide, heights z(x, y).
template <class Z>
std::string tin_file(double step, Z z) {
  std::string text =
      R"(<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml"
 xmlns:dem="http://www.opengis.net/citygml/relief/2.0"><core:cityObjectMember><dem:TINRelief gml:id="t"><dem:lod>1</dem:lod>
<dem:tin><gml:TriangulatedSurface srsName="EPSG:32654"><gml:trianglePatches>
)";
  char point[96];
  const auto pos = [&](double x, double y) {
    std::snprintf(point, sizeof point, "%.4f %.4f %.6f ", kEast0 + x, kNorth0 + y, z(x, y));
    return std::string(point);
  };
  for (double x = -60; x < 60; x += step)
    for (double y = -60; y < 60; y += step) {
      const auto tri = [&](double ax, double ay, double bx, double by, double cx, double cy) {
        text += "<gml:Triangle><gml:exterior><gml:LinearRing><gml:posList>" + pos(ax, ay) + pos(bx, by) + pos(cx, cy) +
                pos(ax, ay) + "</gml:posList></gml:LinearRing></gml:exterior></gml:Triangle>\n";
      };
      tri(x, y, x + step, y, x + step, y + step);
      tri(x, y, x + step, y + step, x, y + step);
    }
  return text +
         "</gml:trianglePatches></gml:TriangulatedSurface></dem:tin></dem:TINRelief></core:cityObjectMember></"
         "core:CityModel>\n";
}

// The stand-in placement: the TIN's triangles less the origin.
TriangleMesh terrain_mesh(const std::string& gml) {
  const CityModel model = parse_citygml(gml, "tin.gml");
  TriangleMesh mesh;
  for (const CitySurface& s : model.objects.at(0).surfaces) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (const Vec3& p : s.rings.at(0)) mesh.vertices.emplace_back(p.x - kEast0, p.y - kNorth0, p.z);
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

double plane(double x, double y) { return 2.0 + 0.03 * x + 0.015 * y; }

TEST(TerrainSurface, HeightOfATinIsItsPlane) {
  const TerrainSurface terrain(terrain_mesh(tin_file(20, plane)));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-60, 60);
  for (int k = 0; k < 200; ++k) {
    const double x = u(rng), y = u(rng);
    const auto h = terrain.height_at(x, y);
    ASSERT_TRUE(h) << x << " " << y;
    // Linear interpolation of a plane is exact; the file's 6 decimals bound the error.
    EXPECT_NEAR(*h, plane(x, y), 1e-5);
  }
  EXPECT_FALSE(terrain.height_at(61, 0));
  EXPECT_FALSE(terrain.height_at(0, -60.5));
}

TEST(TerrainSurface, GroundThatFollowsTheTerrainMeetsItEverywhere) {
  const TerrainSurface terrain(terrain_mesh(tin_file(20, plane)));
  // A footprint 0.4 m above the slope (PLATEAU's buildings float 0.3–1 m above a flat
  // ground), its ground surface in the slope's plane.
  std::vector<Vec3> ground;
  for (auto [x, y] : {std::pair{-13.0, 4.0}, {-13.0, 17.0}, {-1.5, 17.0}, {-1.5, 4.0}})
    ground.emplace_back(x, y, plane(x, y) + 0.4);
  const auto shift = seating_shift_m(terrain, {ground});
  ASSERT_TRUE(shift);
  EXPECT_NEAR(*shift, -0.4, 1e-5);
  // No gap or overlap over 1 cm anywhere along the ground's edges (issue 16).
  for (size_t k = 0; k < ground.size(); ++k)
    for (double f = 0; f < 1; f += 0.01) {
      const Vec3 p = ground[k] + f * (ground[(k + 1) % ground.size()] - ground[k]);
      EXPECT_NEAR(p.z + *shift, *terrain.height_at(p.x, p.y), 0.01);
    }
}

TEST(TerrainSurface, FlatFloorOnASlopeTouchesAtItsDownhillCornerAndSinksUphill) {
  const TerrainSurface terrain(terrain_mesh(tin_file(20, plane)));
  const std::vector<Vec3> floor{{0, 0, 5}, {0, 8, 5}, {10, 8, 5}, {10, 0, 5}};
  const auto shift = seating_shift_m(terrain, {floor});
  ASSERT_TRUE(shift);
  // The lowest terrain under the floor is at (0, 0): 2 m; the floor at 5 m comes down 3 m.
  EXPECT_NEAR(*shift, -3.0, 1e-5);
  // Uphill, at (10, 8), it then lies 0.03·10 + 0.015·8 = 0.42 m into the slope.
  EXPECT_NEAR(*terrain.height_at(10, 8) - (5 + *shift), 0.42, 1e-5);
}

TEST(TerrainSurface, ABuildingMeshMovesByItsGroundTriangles) {
  const TerrainSurface terrain(terrain_mesh(tin_file(20, plane)));
  // A 4 m cube floating 1.2 m above the slope at its downhill corner (2, 2): its two
  // ground triangles (facing down) and a roof triangle 4 m up.
  TriangleMesh cube;
  const double floor = plane(2, 2) + 1.2;
  cube.vertices = {{2, 2, floor},     {2, 6, floor},     {6, 6, floor},    {6, 2, floor},
                   {2, 2, floor + 4}, {6, 2, floor + 4}, {6, 6, floor + 4}};
  cube.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
  const auto shift = seat_on_terrain(terrain, cube, {true, true, false});
  ASSERT_TRUE(shift);
  EXPECT_NEAR(*shift, -1.2, 1e-5);
  EXPECT_NEAR(cube.vertices[0].z, plane(2, 2), 1e-5);      // the downhill corner on the terrain
  EXPECT_NEAR(cube.vertices[4].z, plane(2, 2) + 4, 1e-5);  // the roof moved with it
}

TEST(TerrainSurface, ABlockWithoutAFloorIsSetDownByItsWallsBottomEdges) {
  const TerrainSurface terrain(terrain_mesh(tin_file(20, plane)));
  // Two walls of a 4 m block (no floor, no ground flags), their bottom 1.2 m above the
  // slope at its downhill corner (2, 2): set down there, as the same block with a floor.
  TriangleMesh walls;
  const double bottom = plane(2, 2) + 1.2;
  walls.vertices = {{2, 2, bottom},     {6, 2, bottom}, {6, 2, bottom + 4},
                    {2, 2, bottom + 4}, {2, 6, bottom}, {2, 6, bottom + 4}};
  walls.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 0, 3}, {4, 3, 5}};
  const auto shift = seat_on_terrain(terrain, walls, {false, false, false, false});
  ASSERT_TRUE(shift);
  EXPECT_NEAR(*shift, -1.2, 1e-5);
  EXPECT_NEAR(walls.vertices[0].z, plane(2, 2), 1e-5);
}

TEST(TerrainSurface, AHollowBetweenCornersIsSeen) {
  // A valley along x = 5 (0.2 m per m either side): the corners of a 10 m floor see
  // terrain 1 m high, the middle of its edges 0 m.
  const TerrainSurface terrain(terrain_mesh(tin_file(5, [](double x, double) { return 0.2 * std::abs(x - 5); })));
  const std::vector<Vec3> floor{{0, 0, 3}, {0, 8, 3}, {10, 8, 3}, {10, 0, 3}};
  const auto shift = seating_shift_m(terrain, {floor});
  ASSERT_TRUE(shift);
  EXPECT_NEAR(*shift, -3.0, 1e-5);  // corners alone would give -2
  EXPECT_FALSE(seating_shift_m(terrain, {{{100, 100, 0}, {101, 100, 0}, {101, 101, 0}}}));
}

}  // namespace
}  // namespace skylit
