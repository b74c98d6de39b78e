// Fresnel reflectance: the closed forms it must reduce to (normal incidence,
// Brewster's angle, grazing, total internal reflection), the classic real-arithmetic
// formula for conductors, aluminium's measured reflectance, window panes, and the
// tables the materials read it from.
#include "skylit/material/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "skylit/core/vec3.h"
#include "skylit/material/angular_table.h"
#include "skylit/material/optical_constants.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {
namespace {

// The conductor formula in real arithmetic (Born & Wolf §14.2; e.g. pbrt-v3
// FrConductor): an independent check of the complex one.
double classic_conductor(double cos_i, double n, double k) {
  const double c2 = cos_i * cos_i, s2 = 1 - c2;
  const double t0 = n * n - k * k - s2;
  const double a2b2 = std::sqrt(t0 * t0 + 4 * n * n * k * k);
  const double a = std::sqrt(0.5 * (a2b2 + t0));
  const double rs = (a2b2 + c2 - 2 * a * cos_i) / (a2b2 + c2 + 2 * a * cos_i);
  const double t3 = c2 * a2b2 + s2 * s2, t4 = 2 * a * cos_i * s2;
  const double rp = rs * (t3 - t4) / (t3 + t4);
  return 0.5 * (rs + rp);
}

TEST(Fresnel, NormalIncidenceIsTheClosedForm) {
  for (const auto eta : {std::complex<double>(1.5, 0), std::complex<double>(1.0, 6.6), std::complex<double>(0.5, 2.0),
                         std::complex<double>(2.7, 8.4)}) {
    const double n = eta.real(), k = eta.imag();
    const double expected = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    EXPECT_NEAR(fresnel_reflectance(1.0, eta), expected, 1e-12) << eta;
    EXPECT_NEAR(fresnel_normal_incidence(eta), expected, 1e-15) << eta;
  }
}

TEST(Fresnel, DielectricOfIndexOneAndAHalfReflectsFourPerCentAtNormalIncidence) {
  EXPECT_NEAR(fresnel_reflectance(1.0, 1.5), 0.04, 1e-12);
}

TEST(Fresnel, TendsToOneAtGrazingIncidence) {
  for (const auto eta : {std::complex<double>(1.5, 0), std::complex<double>(1.0, 6.6)}) {
    EXPECT_NEAR(fresnel_reflectance(0.0, eta), 1.0, 1e-12) << eta;
    EXPECT_GT(fresnel_reflectance(1e-4, eta), 0.999) << eta;
    // And rises monotonically toward it over the last few degrees.
    EXPECT_LT(fresnel_reflectance(std::cos(radians(80)), eta), fresnel_reflectance(std::cos(radians(89)), eta));
  }
}

TEST(Fresnel, IndexOneIsNoInterfaceAtEveryAngle) {
  // Issue 19, item 3: η = 1 divided 0 by 0 at grazing incidence (NaN pixels from glass
  // with "ior": 1). With no interface nothing is reflected, at any angle; the pane then
  // transmits all but its bulk absorption.
  for (const double cos_i : {0.0, 1e-300, 1e-8, 0.5, 1.0}) {
    const FresnelSP r = fresnel_sp(cos_i, 1.0);
    EXPECT_EQ(r.s, 0.0) << cos_i;
    EXPECT_EQ(r.p, 0.0) << cos_i;
    const PaneOptics pane = pane_optics(cos_i, 1.0, 0.0, 0.006, 550.0);
    EXPECT_TRUE(std::isfinite(pane.reflectance) && std::isfinite(pane.transmittance)) << cos_i;
    EXPECT_EQ(pane.reflectance, 0.0) << cos_i;
  }
  // Continuous with its neighbours away from grazing: η = 1 + 1e-9 reflects ~1e-19 at normal incidence.
  EXPECT_NEAR(fresnel_reflectance(1.0, 1.0 + 1e-9), 0.0, 1e-15);
}

TEST(Fresnel, BrewsterAngleHasNoParallelReflectance) {
  const double n = 1.5;
  const double brewster = std::atan(n);  // 56.31°
  const FresnelSP r = fresnel_sp(std::cos(brewster), n);
  EXPECT_NEAR(r.p, 0.0, 1e-15);
  EXPECT_NEAR(r.unpolarised(), r.s / 2, 1e-15);
  // R_s there is ((n² − 1)/(n² + 1))² (Born & Wolf §1.5.3).
  EXPECT_NEAR(r.s, std::pow((n * n - 1) / (n * n + 1), 2), 1e-12);
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double eta = 1 / 1.5;              // from glass into air
  const double critical = std::asin(eta);  // 41.8°
  EXPECT_NEAR(fresnel_reflectance(std::cos(critical + 0.01), eta), 1.0, 1e-12);
  EXPECT_NEAR(fresnel_reflectance(std::cos(radians(70)), eta), 1.0, 1e-12);
  EXPECT_LT(fresnel_reflectance(std::cos(critical - 0.05), eta), 0.5);
  EXPECT_NEAR(fresnel_reflectance(1.0, eta), 0.04, 1e-12);  // the same 4 % from either side
}

TEST(Fresnel, ComplexFormMatchesTheClassicConductorFormula) {
  for (const auto& nk : {std::pair{1.0, 6.6}, std::pair{0.5, 2.0}, std::pair{2.7, 8.4}, std::pair{1.5, 1e-7}})
    for (double deg = 0; deg <= 90; deg += 2.5) {
      const double c = std::cos(radians(deg));
      EXPECT_NEAR(fresnel_reflectance(c, {nk.first, nk.second}), classic_conductor(c, nk.first, nk.second), 1e-9)
          << nk.first << " " << nk.second << " at " << deg << "°";
    }
}

TEST(Fresnel, AluminiumReflectsAboutNinetyTwoPerCentAtNormalIncidence) {
  // Rakić (1995): 0.91–0.93 across the visible for evaporated aluminium.
  const ComplexIor& al = aluminium_ior();
  for (int i = 0; i < kGrid.bins; ++i) {
    if (kGrid.center_nm(i) < 400 || kGrid.center_nm(i) > 700) continue;
    const double r = fresnel_normal_incidence(al.at(i));
    EXPECT_GT(r, 0.89) << kGrid.center_nm(i);
    EXPECT_LT(r, 0.935) << kGrid.center_nm(i);
  }
  // The bin 550–560 nm against the closed form from the table read at its centre.
  const Tabulated n = embedded_table("metal_aluminium_nk.csv", 1), k = embedded_table("metal_aluminium_nk.csv", 2);
  const double n555 = n(555.0), k555 = k(555.0);
  const double closed = ((n555 - 1) * (n555 - 1) + k555 * k555) / ((n555 + 1) * (n555 + 1) + k555 * k555);
  EXPECT_NEAR(fresnel_reflectance(1.0, al.at(17)), closed, 1e-3);
  EXPECT_NEAR(closed, 0.916, 0.003);
}

TEST(Fresnel, PaneWithoutAbsorptionReflectsTwoROverOnePlusR) {
  const PaneOptics p = pane_optics(1.0, 1.5, 0.0, 0.006, 550);
  EXPECT_NEAR(p.reflectance, 2 * 0.04 / 1.04, 1e-12);
  EXPECT_NEAR(p.transmittance, 0.96 / 1.04, 1e-12);
  for (double c : {0.0, 0.1, 0.5, 0.9}) {
    const PaneOptics q = pane_optics(c, 1.5, 0.0, 0.006, 550);
    EXPECT_NEAR(q.reflectance + q.transmittance, 1.0, 1e-12) << c;
  }
}

TEST(Fresnel, FloatGlassPaneTransmitsAboutEightyEightPerCent) {
  // Clear float glass 6 mm: light transmittance about 0.88, reflectance 0.08
  // (manufacturers' data sheets, EN 410 values).
  const ComplexIor& glass = soda_lime_glass_ior();
  const PaneOptics p = pane_optics(1.0, glass.n[17], glass.k[17], 0.006, kGrid.center_nm(17));
  EXPECT_NEAR(p.transmittance, 0.885, 0.015);
  EXPECT_NEAR(p.reflectance, 0.08, 0.005);
  EXPECT_LT(p.reflectance + p.transmittance, 1.0);  // it absorbs a little
}

TEST(Fresnel, TablesMatchTheExactCurves) {
  // Aluminium and glass in the bins at the ends and the middle of the visible.
  for (const ComplexIor* ior : {&aluminium_ior(), &soda_lime_glass_ior()}) {
    const AngularTable table([&](double c) {
      Spectrum s;
      for (int i = 0; i < Spectrum::size(); ++i) s[i] = static_cast<float>(fresnel_reflectance(c, ior->at(i)));
      return s;
    });
    double worst = 0;
    for (int j = 0; j <= 20000; ++j) {
      const double c = j / 20000.0;
      const Spectrum s = table.at(c);
      for (int i : {0, 17, 39}) worst = std::max(worst, std::abs(s[i] - fresnel_reflectance(c, ior->at(i))));
    }
    EXPECT_LT(worst, 1e-4);
  }
}

TEST(Fresnel, HemisphericalMeanOfADielectric) {
  // n = 1.5: 0.0918 (e.g. the diffuse Fresnel reflectance tabulated in the
  // literature on layered media; Simpson's rule on the table's 513 nodes).
  const AngularTable table([](double c) { return Spectrum(static_cast<float>(fresnel_reflectance(c, 1.5))); });
  EXPECT_NEAR(table.hemispherical_mean()[0], 0.0918, 5e-4);
}

}  // namespace
}  // namespace skylit
