// The CIE road-surface r-tables (material/road_reflection.h): the data against the
// figures CIE 144 publishes for each class, the look-up, the angles, and the BRDF's
// blend from the table (views near 1°) to a diffuse surface (steep views).
#include "skylit/material/road_reflection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {
namespace {

struct ClassFigures {
  const char* name;
  double q0, s1;
};

// CIE 144:2001 Table 2 (also W. van Bommel, Road Lighting, 2015, Table 12.2): the
// standard classes' Q0 and specular factor S1.
constexpr ClassFigures kPublished[] = {{"R1", 0.10, 0.25}, {"R2", 0.07, 0.58}, {"R3", 0.07, 1.11},
                                       {"R4", 0.08, 1.55}, {"C1", 0.10, 0.24}, {"C2", 0.07, 0.97}};

TEST(RoadReflectionTable, SpecularFactorsAreThePublishedOnes) {
  // S1 = r(0, 2)/r(0, 0) from the tabulated data; CIE gives it to two decimals, so
  // a transcription or indexing error of more than 0.005 shows.
  for (const ClassFigures& c : kPublished) {
    const auto table = RoadReflectionTable::standard(c.name);
    ASSERT_TRUE(table) << c.name;
    EXPECT_NEAR(table->specular_factor(), c.s1, 0.006) << c.name;
    EXPECT_DOUBLE_EQ(table->nominal_q0(), c.q0);
  }
  EXPECT_FALSE(RoadReflectionTable::standard("R5"));
}

TEST(RoadReflectionTable, MeanLuminanceCoefficientIsThePublishedQ0) {
  // Q0 = ∫ q dΩ / Ω over the tabulated directions of incidence. With q = r/cos³γ and
  // t = tan γ, q dΩ = r t dt dβ, and Ω = ∫ sin γ dγ dβ: a trapezoid quadrature over the
  // cells whose four corners the table fills. CIE computes Q0 with its own weights over
  // a domain bounded a little differently (CIE 144, Annex), so agreement within 6 %
  // (measured: 0.3–5.2 %) says that the whole table, not one cell, is right.
  for (const ClassFigures& c : kPublished) {
    const auto table = RoadReflectionTable::standard(c.name);
    const auto& t = table->tan_gammas();
    const auto& b = table->betas_deg();
    double integral = 0, solid_angle = 0;
    for (size_t i = 0; i + 1 < t.size(); ++i)
      for (size_t j = 0; j + 1 < b.size(); ++j) {
        const double corners[4] = {table->at(b[j], t[i]), table->at(b[j + 1], t[i]), table->at(b[j], t[i + 1]),
                                   table->at(b[j + 1], t[i + 1])};
        if (*std::min_element(corners, corners + 4) <= 0) continue;
        const double d_beta = radians(b[j + 1] - b[j]);
        integral +=
            (corners[0] + corners[1] + corners[2] + corners[3]) / 4 * (t[i + 1] * t[i + 1] - t[i] * t[i]) / 2 * d_beta;
        solid_angle += (std::cos(std::atan(t[i])) - std::cos(std::atan(t[i + 1]))) * d_beta;
      }
    EXPECT_NEAR(integral / solid_angle, c.q0, 0.06 * c.q0) << c.name;
  }
}

TEST(RoadReflectionTable, LooksUpTabulatedCellsAndInterpolatesBetween) {
  const auto r3 = RoadReflectionTable::standard("R3");
  // Cells of the published R3 table (values × 10⁻⁴).
  EXPECT_DOUBLE_EQ(r3->at(0, 0), 294e-4);
  EXPECT_DOUBLE_EQ(r3->at(90, 0.5), 204e-4);
  EXPECT_DOUBLE_EQ(r3->at(45, 3), 18e-4);
  EXPECT_DOUBLE_EQ(r3->at(180, 4.5), 8.5e-4);
  EXPECT_DOUBLE_EQ(r3->at(-90, 0.5), 204e-4);  // symmetric about β = 0
  EXPECT_DOUBLE_EQ(r3->at(270, 0.5), 204e-4);
  EXPECT_EQ(r3->at(180, 12), 0.0);  // an empty cell: outside the domain
  EXPECT_EQ(r3->at(0, 12.5), 0.0);  // beyond the table
  // Bilinear: the middle of the cell (β 0–2, tan γ 0.25–0.5) is its corners' mean.
  EXPECT_NEAR(r3->at(1, 0.375), (326 + 326 + 344 + 344) / 4.0 * 1e-4, 1e-12);
}

TEST(RoadAngles, BetaIsZeroWithTheLampBeyondThePoint) {
  const Vec3 up{0, 0, 1};
  const Vec3 to_viewer = normalize(Vec3{0, -60, 1.5});
  // Lamp 8 m up, 8 m beyond the point as the observer looks: tan γ = 1, β = 0.
  RoadAngles a = road_angles(up, normalize(Vec3{0, 8, 8}), to_viewer);
  EXPECT_NEAR(a.tan_gamma, 1.0, 1e-12);
  EXPECT_NEAR(a.beta_deg, 0.0, 1e-9);
  // Between observer and point: β = 180°; beside: 90°.
  EXPECT_NEAR(road_angles(up, normalize(Vec3{0, -8, 8}), to_viewer).beta_deg, 180.0, 1e-9);
  a = road_angles(up, normalize(Vec3{4, 0, 8}), to_viewer);
  EXPECT_NEAR(a.beta_deg, 90.0, 1e-9);
  EXPECT_NEAR(a.tan_gamma, 0.5, 1e-12);
}

TEST(RoadMaterial, IsTheScaledTableNearGrazingAndDiffuseForSteepViews) {
  const RoadMaterial road(RoadReflectionTable::standard("R3"), 0.084);  // Q0 1.2 × the class's
  const Vec3 up{0, 0, 1};
  const Vec3 to_light = normalize(Vec3{4, 0, 8});  // β = 90°, tan γ = 0.5
  const double cos_gamma = to_light.z;
  const double table_q = 1.2 * 204e-4 / (cos_gamma * cos_gamma * cos_gamma);
  // α = 1°: the table, scaled by q0/Q0.
  const Vec3 at_1_deg{0, -std::cos(radians(1.0)), std::sin(radians(1.0))};
  EXPECT_NEAR(road.brdf(up, to_light, at_1_deg), table_q, 1e-12);
  // α = 30°: Lambertian with f = Q0.
  const Vec3 at_30_deg{0, -std::cos(radians(30.0)), std::sin(radians(30.0))};
  EXPECT_NEAR(road.brdf(up, to_light, at_30_deg), 0.084, 1e-12);
  // Half-way through the blend (α = 10.75°): the mean of the two.
  const Vec3 half{0, -std::cos(radians(10.75)), std::sin(radians(10.75))};
  EXPECT_NEAR(road.brdf(up, to_light, half), 0.5 * (table_q + 0.084), 1e-9);
  // Nothing from below.
  EXPECT_EQ(road.brdf(up, Vec3{0, 0, -1}, at_1_deg), 0.0);
}

}  // namespace
}  // namespace skylit
