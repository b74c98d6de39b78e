// A car's headlamps (lights/headlamps.h): the built beams, read back through the
// tabulated luminaire as the renderer reads them, meet the ECE R112 test points and
// zones we build to; the pair stands where the car's position and heading say.
#include "skylit/lights/headlamps.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.h"
#include "skylit/core/angles.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit {
namespace {

// The world direction h degrees right of the car's heading and v degrees up.
Vec3 beam_direction(double heading_deg, double h_deg, double v_deg) {
  const double a = radians(heading_deg + h_deg), v = radians(v_deg);
  return {std::cos(v) * std::sin(a), std::cos(v) * std::cos(a), std::sin(v)};
}

TEST(Headlamps, BeamsMeetTheRegulationsTestPoints) {
  for (Beam beam : {Beam::low, Beam::high})
    for (double heading : {0.0, 37.0, 250.0}) {
      const HeadlampPair pair = place_headlamps({3, -4, 0}, heading);
      const Luminaire lamp = headlamp_luminaire(pair.right, pair.forward, beam);
      for (const BeamTestPoint& p : ece_r112_test_points(beam)) {
        const double i = lamp.intensity(beam_direction(heading, p.h_deg, p.v_deg));
        EXPECT_GE(i, p.min_cd) << p.name << " heading " << heading;
        if (p.max_cd > 0) {
          EXPECT_LE(i, p.max_cd) << p.name << " heading " << heading;
        }
      }
    }
}

TEST(Headlamps, LowBeamKeepsZoneThreeDarkAndZonesOneAndFourWithinLimits) {
  // R112's zones, as we take them (docs/lights.md): III above the cut-off (8°L–8°R from
  // 1°U to 4°U, and 8°L–1°L from 0.57°U) at most 625 cd; IV, the band 0.86°D–1.72°D
  // from 5.15°L to 5.15°R, at least 2500 cd; I, 9°L–9°R below 1.72°D to 5°D, at most
  // twice the value at 50R. Sampled every 0.25°.
  const double heading = 120;
  const HeadlampPair pair = place_headlamps({0, 0, 0}, heading);
  const Luminaire lamp = headlamp_luminaire(pair.left, pair.forward, Beam::low);
  const auto at = [&](double h, double v) { return lamp.intensity(beam_direction(heading, h, v)); };
  const double i50r = at(1.72, -0.86);
  double zone3 = 0, zone4 = 1e9, zone1 = 0;
  for (double h = -9; h <= 9; h += 0.25) {
    for (double v = -5; v <= 4; v += 0.25) {
      if (std::abs(h) <= 8 && v >= 1) zone3 = std::max(zone3, at(h, v));
      if (h >= -8 && h <= -1 && v >= 0.57) zone3 = std::max(zone3, at(h, v));
      if (v <= -1.72) zone1 = std::max(zone1, at(h, v));
    }
  }
  for (double h = -5.15; h <= 5.15; h += 0.25)
    for (double v = -1.72; v <= -0.86; v += 0.1) zone4 = std::min(zone4, at(h, v));
  EXPECT_LE(zone3, 625);
  EXPECT_GE(zone4, 2500);
  EXPECT_LE(zone1, 2 * i50r);
  // The table follows the shape it was built from: within 3 % at the test points (the
  // bilinear (C, γ) interpolation on 1° × 0.1° cells), far from the cut-off's step.
  for (const BeamTestPoint& p : ece_r112_test_points(Beam::low)) {
    const double shape = headlamp_candela(Beam::low, p.h_deg, p.v_deg);
    EXPECT_NEAR(at(p.h_deg, p.v_deg), shape, 0.03 * shape + 5) << p.name;
  }
}

TEST(Headlamps, ThePairStandsWhereTheHeadingSays) {
  // Heading east from (10, 5, 2): forward +x, the driver's right is south.
  const HeadlampPair pair = place_headlamps({10, 5, 2}, 90);
  EXPECT_NEAR(pair.forward.x, 1, 1e-12);
  EXPECT_NEAR(pair.left.x, 10, 1e-12);
  EXPECT_NEAR(pair.left.y, 5.7, 1e-12);
  EXPECT_NEAR(pair.right.y, 4.3, 1e-12);
  EXPECT_NEAR(pair.left.z, 2.65, 1e-12);
  // From a scene file: two lights per car, their beams toward the heading (north-west).
  testing::TempDir dir;
  const Scene scene = load_scene(dir.write(
      "cars.json", testing::small_scene_with(
                       "cars", R"([{"name": "car", "position": [1, 2, 0], "heading_deg": 315, "beam": "high"}])")));
  ASSERT_EQ(scene.lights.size(), 2u);
  const Vec3 mid = (scene.lights[0].luminaire.position() + scene.lights[1].luminaire.position()) * 0.5;
  EXPECT_NEAR(mid.x, 1, 1e-9);
  EXPECT_NEAR(mid.y, 2, 1e-9);
  EXPECT_NEAR(mid.z, kHeadlampHeightM, 1e-9);
  EXPECT_NEAR(length(scene.lights[0].luminaire.position() - scene.lights[1].luminaire.position()), kHeadlampSpacingM,
              1e-9);
  const Luminaire& lamp = scene.lights[0].luminaire;
  EXPECT_GT(lamp.intensity(beam_direction(315, 0, 0)), 48000);
  EXPECT_EQ(lamp.intensity(beam_direction(135, 0, 0)), 0);
}

}  // namespace
}  // namespace skylit
