// Sky light shared between samples of one tile (render/tile_sliver_values.h): a sample
// takes the nearest earlier value on the same surface within 2 pixels and within reach,
// and nothing else.
#include "skylit/render/tile_sliver_values.h"

#include <gtest/gtest.h>

namespace skylit {
namespace {

// A point on the wall x = 0 (normal +x) seen from 100 m, of material 1.
SurfacePoint wall_point(double y, double z) { return SurfacePoint{{0, y, z}, {1, 0, 0}, 100.0, 1}; }

CachedSkyLight value(float diffuse) { return {Irradiance(diffuse), Radiance(0.0f), Irradiance(0.0f)}; }

TEST(TileSliverValues, SharesTheNearestValueOnTheSameSurfaceWithinTwoPixels) {
  TileSliverValues values;
  EXPECT_EQ(values.find(10.25, 10.25, wall_point(0, 0)), nullptr);  // nothing yet
  values.add(10.25, 10.25, wall_point(0, 0), value(1));
  values.add(11.75, 10.25, wall_point(0.1, 0), value(2));
  // Nearest of the two, on screen.
  const CachedSkyLight* near_first = values.find(10.75, 11.25, wall_point(0.05, 0.1));
  ASSERT_NE(near_first, nullptr);
  EXPECT_EQ(near_first->diffuse_irradiance[0], 1.0f);
  const CachedSkyLight* near_second = values.find(12.25, 11.75, wall_point(0.15, 0.1));
  ASSERT_NE(near_second, nullptr);
  EXPECT_EQ(near_second->diffuse_irradiance[0], 2.0f);
  // Beyond 2 pixels of both.
  EXPECT_EQ(values.find(14.25, 10.25, wall_point(0.2, 0)), nullptr);
  EXPECT_EQ(values.find(10.25, 12.75, wall_point(0, -0.2)), nullptr);
}

TEST(TileSliverValues, RefusesAnotherSurfaceOrAPointOutOfReach) {
  TileSliverValues values;
  values.add(5.25, 5.25, wall_point(0, 0), value(1));
  SurfacePoint other_material = wall_point(0, 0.1);
  other_material.material = 2;
  EXPECT_EQ(values.find(5.75, 5.25, other_material), nullptr);
  SurfacePoint other_plane = wall_point(0, 0.1);  // a parallel wall 0.5 m behind
  other_plane.position.x = -0.5;
  EXPECT_EQ(values.find(5.75, 5.25, other_plane), nullptr);
  SurfacePoint turned = wall_point(0, 0.1);  // a reveal at right angles
  turned.normal = {0, 1, 0};
  EXPECT_EQ(values.find(5.75, 5.25, turned), nullptr);
  // 6 m away along the same wall: beyond 5 % of the 100 m distance.
  EXPECT_EQ(values.find(5.75, 5.25, wall_point(6, 0)), nullptr);
  EXPECT_NE(values.find(5.75, 5.25, wall_point(4, 0)), nullptr);
}

}  // namespace
}  // namespace skylit
