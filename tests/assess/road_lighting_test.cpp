// The EN 13201-3 figures (assess/road_lighting.h) against hand calculations: one lamp
// over an R3 road, placed so that the lane's centre-line points fall on the table's
// nodes (L = I r / h² with r typed from the published table), a staggered row computed
// point by point here, and a shadow from the scene's geometry.
#include "skylit/assess/road_lighting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "skylit/core/angles.h"
#include "skylit/geometry/primitives.h"
#include "skylit/lights/lamp_rows.h"

namespace skylit {
namespace {

constexpr double kCandela = 1000;

SceneLight isotropic_lamp(const Vec3& position) {
  return {"lamp", Luminaire(position, IntensityDistribution::isotropic(kCandela)), Spectrum(1.0f)};
}

// A one-lane road 3.5 m wide running north from the origin, R3 at its nominal Q0,
// a field of 30 m: rows at 1.5, 4.5, …, 28.5 m.
RoadLightingSettings one_lane_road() {
  RoadLightingSettings road;
  road.start = {0, 0, 0};
  road.direction_deg = 0;
  road.field_length_m = 30;
  road.width_m = 3.5;
  road.lanes = 1;
  road.r_table = RoadReflectionTable::standard("R3");
  road.q0 = 0.07;
  return road;
}

TEST(RoadLighting, SingleLampLuminanceOnTheLaneCentreIsTheHandCalculation) {
  // Lamp 6 m above the first row's centre point: the centre-line points lie 3i m on,
  // tan γ = 0.5 i, and the observer 60 m back sees the lamp between itself and each
  // point: β = 180°. r(180°, 0.5 i) × 10⁴ from the published R3 table; L = I r / h².
  const RoadLightingSettings road = one_lane_road();
  const std::vector<SceneLight> lights{isotropic_lamp({0, 1.5, 6})};
  const RoadLightingFigures f = compute_road_lighting(road, lights, nullptr);
  ASSERT_EQ(f.rows, 10);
  ASSERT_EQ(f.luminance_columns, 3);
  const double r_published[10] = {294, 194, 100, 62, 38, 25, 17, 13, 9.9, 8.5};
  for (int i = 0; i < 10; ++i) {
    const double expected = kCandela * r_published[i] * 1e-4 / 36;
    // Exact but for rounding: 2 % is the brief's bound, 1e-9 what the formula allows.
    EXPECT_NEAR(f.luminance_by_observer[0][static_cast<size_t>(3 * i + 1)], expected, 1e-9 * expected) << "row " << i;
  }
  EXPECT_NEAR(f.longitudinal_uniformity, 8.5 / 294, 1e-9);
}

// The figures computed here from their definitions, point by point, for isotropic
// lamps on a flat road with no obstacles (the hand calculation, in a loop).
struct HandFigures {
  double l_av = 1e300, u_o = 1e300, u_l = 1e300, e_av, e_min;
};

HandFigures hand_figures(const RoadLightingSettings& road, const std::vector<Vec3>& lamps) {
  const RoadReflectionTable& table = *road.r_table;
  const int rows = 10;  // fields ≤ 30 m
  const double d = road.field_length_m / rows, lane = road.width_m / road.lanes;
  HandFigures h;
  // Road coordinates: the road runs along +y from the origin, across = −x (left of north is west).
  for (int k = 0; k < road.lanes; ++k) {
    const double eye_x = -(-road.width_m / 2 + (k + 0.5) * lane);
    std::vector<double> all, centre;
    for (int i = 0; i < rows; ++i)
      for (int kk = 0; kk < road.lanes; ++kk)
        for (int j = 0; j < 3; ++j) {
          const double px = -(-road.width_m / 2 + kk * lane + (j + 0.5) * lane / 3), py = (i + 0.5) * d;
          double l = 0;
          for (const Vec3& lamp : lamps) {
            const double dx = lamp.x - px, dy = lamp.y - py, height = lamp.z;
            const double tan_gamma = std::hypot(dx, dy) / height;
            // β: between the plan directions point→lamp and observer→point.
            const double ox = px - eye_x, oy = py - (-60.0);
            double beta = 0;
            if (std::hypot(dx, dy) > 0)
              beta = degrees(
                  std::acos(std::clamp((dx * ox + dy * oy) / (std::hypot(dx, dy) * std::hypot(ox, oy)), -1.0, 1.0)));
            l += kCandela * table.at(beta, tan_gamma) * (road.q0 / table.nominal_q0()) / (height * height);
          }
          all.push_back(l);
          if (kk == k && j == 1) centre.push_back(l);
        }
    const double av = std::accumulate(all.begin(), all.end(), 0.0) / all.size();
    h.l_av = std::min(h.l_av, av);
    h.u_o = std::min(h.u_o, *std::min_element(all.begin(), all.end()) / av);
    h.u_l = std::min(h.u_l,
                     *std::min_element(centre.begin(), centre.end()) / *std::max_element(centre.begin(), centre.end()));
  }
  // Illuminance: n = max(3, ⌈W/1.5⌉) across; E = I h / d³.
  const int n = std::max(3, static_cast<int>(std::ceil(road.width_m / 1.5)));
  std::vector<double> e;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < n; ++j) {
      const double px = road.width_m / 2 - (j + 0.5) * road.width_m / n, py = (i + 0.5) * d;
      double sum = 0;
      for (const Vec3& lamp : lamps) {
        const double dist = std::hypot(lamp.x - px, lamp.y - py, lamp.z);
        sum += kCandela * lamp.z / (dist * dist * dist);
      }
      e.push_back(sum);
    }
  h.e_av = std::accumulate(e.begin(), e.end(), 0.0) / e.size();
  h.e_min = *std::min_element(e.begin(), e.end());
  return h;
}

TEST(RoadLighting, SingleLampFiguresAreTheHandCalculation) {
  // Within 2 % (the brief's bound; the two computations differ only in rounding).
  const RoadLightingSettings road = one_lane_road();
  const Vec3 lamp{1.0, 1.5, 6};  // 1 m east of the centre line: columns see different β
  const RoadLightingFigures f = compute_road_lighting(road, {isotropic_lamp(lamp)}, nullptr);
  const HandFigures h = hand_figures(road, {lamp});
  EXPECT_NEAR(f.average_luminance, h.l_av, 0.02 * h.l_av);
  EXPECT_NEAR(f.overall_uniformity, h.u_o, 0.02 * h.u_o);
  EXPECT_NEAR(f.longitudinal_uniformity, h.u_l, 0.02 * h.u_l);
  EXPECT_NEAR(f.average_illuminance, h.e_av, 0.02 * h.e_av);
  EXPECT_NEAR(f.minimum_illuminance, h.e_min, 0.02 * h.e_min);
  // TI: the observer starts where the lamp is 20° up (4.5 m above the eye, 12.36 m
  // ahead) and only there sees it (every later position has it above the roof's
  // cut-off): θ = 20° + 1° from a line of sight 1° down, E = I cos θ / d²,
  // L_v = 10.0 E / θ², TI = 65 L_v / L_av^0.8. (The lamp is 1 m aside: θ and d are
  // taken in 3-D here.)
  const double ahead = 4.5 / std::tan(radians(20.0));
  const Vec3 to_lamp = Vec3{lamp.x, ahead, 4.5};  // from the eye on the centre line
  const double dist = length(to_lamp);
  const Vec3 sight{0, std::cos(radians(1.0)), -std::sin(radians(1.0))};
  const double cos_theta = dot(to_lamp, sight) / dist;
  const double theta = degrees(std::acos(cos_theta));
  const double lv = 9.86 * (1 + std::pow(23.0 / 66.4, 4)) * kCandela * cos_theta / (dist * dist) / (theta * theta);
  const double ti = 65 * lv / std::pow(h.l_av, 0.8);
  EXPECT_NEAR(f.threshold_increment_pct, ti, 0.02 * ti);
}

TEST(RoadLighting, StaggeredRowFiguresAreTheHandCalculation) {
  // Two lanes, 7 m, lamps 8 m up with 1 m overhang alternately on the right and left
  // kerb every 15 m (place_lamp_row), along a centre line 120 m long starting 45 m
  // before the field. Within 2 %.
  RoadLightingSettings road = one_lane_road();
  road.width_m = 7;
  road.lanes = 2;
  LampRowSettings row;
  row.centre_line = {{0, -45, 0}, {0, 75, 0}};
  row.road_width_m = 7;
  row.spacing_m = 15;
  row.height_m = 8;
  row.overhang_m = 1;
  row.arrangement = LampArrangement::staggered;
  std::vector<SceneLight> lights;
  std::vector<Vec3> positions;
  for (const LampPlacement& p : place_lamp_row(row)) {
    lights.push_back(isotropic_lamp(p.position));
    positions.push_back(p.position);
  }
  ASSERT_EQ(positions.size(), 9u);
  EXPECT_NEAR(positions[0].x, 2.5, 1e-12);   // right of north is east: 3.5 − 1
  EXPECT_NEAR(positions[1].x, -2.5, 1e-12);  // then the left kerb
  EXPECT_NEAR(positions[1].y, -30, 1e-12);
  const RoadLightingFigures f = compute_road_lighting(road, lights, nullptr);
  const HandFigures h = hand_figures(road, positions);
  EXPECT_NEAR(f.average_luminance, h.l_av, 0.02 * h.l_av);
  EXPECT_NEAR(f.overall_uniformity, h.u_o, 0.02 * h.u_o);
  EXPECT_NEAR(f.longitudinal_uniformity, h.u_l, 0.02 * h.u_l);
  EXPECT_NEAR(f.average_illuminance, h.e_av, 0.02 * h.e_av);
  EXPECT_NEAR(f.minimum_illuminance, h.e_min, 0.02 * h.e_min);
  EXPECT_GT(f.threshold_increment_pct, 0);
  EXPECT_GT(f.edge_illuminance_ratio, 0.2);
  EXPECT_LT(f.edge_illuminance_ratio, 1.0);  // the lamps stand over the road: darker outside
}

TEST(RoadLighting, TheScenesGeometryShadowsTheRoad) {
  // A wall across the road between the lamp and the far rows: their illuminance and
  // luminance fall to 0; the rows before it keep theirs.
  const RoadLightingSettings road = one_lane_road();
  const std::vector<SceneLight> lights{isotropic_lamp({0, 1.5, 6})};
  RayTracer wall;
  wall.add_mesh(make_box({-10, 14, 0}, {10, 14.5, 5}));  // rows at 16.5 m and beyond are in its shadow
  wall.commit();
  const RoadLightingFigures open = compute_road_lighting(road, lights, nullptr);
  const RoadLightingFigures shaded = compute_road_lighting(road, lights, &wall);
  const int n = shaded.illuminance_columns;
  EXPECT_EQ(shaded.illuminance[static_cast<size_t>(9 * n + 1)], 0.0);  // row 28.5 m
  EXPECT_EQ(shaded.luminance_by_observer[0][static_cast<size_t>(9 * 3 + 1)], 0.0);
  EXPECT_DOUBLE_EQ(shaded.illuminance[1], open.illuminance[1]);  // row 1.5 m
  EXPECT_LT(shaded.average_illuminance, open.average_illuminance);
}

}  // namespace
}  // namespace skylit
