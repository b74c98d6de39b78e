// Lamp rows (lights/lamp_rows.h): where the luminaires stand along a centre line and
// which way they face.
#include "skylit/lights/lamp_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "skylit/core/angles.h"
#include "skylit/lights/luminaire.h"

namespace skylit {
namespace {

LampRowSettings northbound() {
  LampRowSettings row;
  row.centre_line = {{0, 0, 0}, {0, 100, 0}};
  row.road_width_m = 8;
  row.spacing_m = 25;
  row.height_m = 10;
  row.overhang_m = 1.5;
  return row;
}

TEST(LampRows, SingleSidedStandsAtTheRightKerbFacingTheRoad) {
  LampRowSettings row = northbound();
  row.tilt_deg = 10;
  const auto lamps = place_lamp_row(row);
  ASSERT_EQ(lamps.size(), 5u);  // 0, 25, 50, 75, 100
  for (size_t i = 0; i < lamps.size(); ++i) {
    EXPECT_NEAR(lamps[i].position.x, 4 - 1.5, 1e-12);  // right of north is east
    EXPECT_NEAR(lamps[i].position.y, 25.0 * i, 1e-9);
    EXPECT_NEAR(lamps[i].position.z, 10, 1e-12);
    // Tilted 10° toward the road (west), and the street side C90 faces it: the
    // luminaire's C90 direction at γ = 60° points west, C0 along the road.
    EXPECT_NEAR(std::acos(-lamps[i].aim.z), radians(10.0), 1e-12);
    EXPECT_LT(lamps[i].aim.x, 0);
    const Luminaire l(lamps[i].position, IntensityDistribution::isotropic(1), lamps[i].aim, lamps[i].rotation_deg);
    const Vec3 c90 = l.world_direction(90, 60), c0 = l.world_direction(0, 60);
    EXPECT_LT(c90.x, -0.8);
    EXPECT_GT(std::abs(c0.y), 0.8);
  }
}

TEST(LampRows, OppositeAndStaggeredUseBothKerbs) {
  LampRowSettings row = northbound();
  row.arrangement = LampArrangement::opposite;
  auto lamps = place_lamp_row(row);
  ASSERT_EQ(lamps.size(), 10u);
  EXPECT_NEAR(lamps[0].position.x, 2.5, 1e-12);
  EXPECT_NEAR(lamps[1].position.x, -2.5, 1e-12);
  EXPECT_NEAR(lamps[1].position.y, 0, 1e-12);
  row.arrangement = LampArrangement::staggered;
  row.side = RoadSide::left;
  lamps = place_lamp_row(row);
  ASSERT_EQ(lamps.size(), 5u);
  for (size_t i = 0; i < lamps.size(); ++i) EXPECT_NEAR(lamps[i].position.x, i % 2 == 0 ? -2.5 : 2.5, 1e-12);
  // The left kerb's lamps face east.
  const Luminaire l(lamps[0].position, IntensityDistribution::isotropic(1), lamps[0].aim, lamps[0].rotation_deg);
  EXPECT_GT(l.world_direction(90, 60).x, 0.8);
}

TEST(LampRows, FollowsABentCentreLineByDistanceAlongIt) {
  LampRowSettings row = northbound();
  row.centre_line = {{0, 0, 0}, {0, 30, 0}, {40, 30, 2}};  // north 30 m, then east (rising) ~40 m
  row.spacing_m = 20;
  row.first_at_m = 10;
  const auto lamps = place_lamp_row(row);
  ASSERT_EQ(lamps.size(), 4u);  // at 10, 30, 50, 70 m (the line is 70.05 m)
  EXPECT_NEAR(lamps[0].position.y, 10, 1e-9);
  // 50 m along: 20 m into the eastbound segment (of length √(40² + 2²)), right kerb = south.
  const double t = 20 / std::hypot(40.0, 2.0);
  EXPECT_NEAR(lamps[2].position.x, 40 * t, 1e-9);
  EXPECT_NEAR(lamps[2].position.y, 30 - 2.5, 1e-9);
  EXPECT_NEAR(lamps[2].position.z, 2 * t + 10, 1e-9);
}

TEST(LampRows, RefusesDegenerateRows) {
  LampRowSettings row = northbound();
  row.centre_line = {{0, 0, 0}, {0, 0, 0}};
  EXPECT_THROW(place_lamp_row(row), std::invalid_argument);
  row = northbound();
  row.spacing_m = 0;
  EXPECT_THROW(place_lamp_row(row), std::invalid_argument);
}

}  // namespace
}  // namespace skylit
