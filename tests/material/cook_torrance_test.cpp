// The Cook–Torrance lobe in its normalised form: Beckmann's D integrates to 1 over
// projected facet area, the lobe (with F = 1) never reflects more than it receives
// and nearly all of it for smooth surfaces seen head-on, and f(l, v) = f(v, l).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skylit/material/microfacet.h"
#include "skylit/material/reflection.h"

namespace skylit {
namespace {

const Vec3 kNormal{0, 0, 1};

Vec3 from_spherical(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(CookTorrance, BeckmannDistributionIsNormalised) {
  // ∫ D(α) cos α dω = 2π ∫₀^{π/2} D(α) cos α sin α dα, midpoint rule fine enough for
  // the narrowest lobe (step m/200 at m = 0.05).
  for (const double m : {0.05, 0.1, 0.2, 0.5, 1.0}) {
    const int steps = 40000;
    const double h = (kPi / 2) / steps;
    double sum = 0;
    for (int i = 0; i < steps; ++i) {
      const double a = (i + 0.5) * h;
      sum += beckmann_distribution(std::cos(a), m) * std::cos(a) * std::sin(a) * h;
    }
    EXPECT_NEAR(2 * kPi * sum, 1.0, 1e-3) << "m = " << m;
  }
}

// ∫ f_s(l, v) (n·l) dω_l with F = 1, integrated over half vectors: l = 2(v·h)h − v
// and dω_l = 4 (v·h) dω_h, so the integrand is D G (v·h) / (n·v) on the half-vector
// hemisphere (half vectors whose l is below the horizon give G = 0).
double directional_albedo(double m, double view_theta) {
  const Vec3 v = from_spherical(view_theta, 0);
  const int n_theta = 3000, n_phi = 360;
  const double d_theta = (kPi / 2) / n_theta, d_phi = 2 * kPi / n_phi;
  double sum = 0;
  for (int i = 0; i < n_theta; ++i) {
    const double theta = (i + 0.5) * d_theta;
    for (int j = 0; j < n_phi; ++j) {
      const Vec3 h = from_spherical(theta, (j + 0.5) * d_phi);
      const double vh = dot(v, h);
      if (vh <= 0) continue;
      const Vec3 l = 2 * vh * h - v;
      const MicrofacetTerm t = cook_torrance_term(kNormal, l, v, m);
      sum += t.brdf_without_fresnel * dot(kNormal, l) * 4 * vh * std::sin(theta) * d_theta * d_phi;
    }
  }
  return sum;
}

TEST(CookTorrance, WhiteFurnaceDirectionalAlbedoIsAtMostOne) {
  // Tolerances: the quadrature is good to about 1e-3 (the step in θ_h is m/100 at
  // m = 0.05). Energy: A ≤ 1 + 2e-3 everywhere. Smooth surface seen head-on: G is
  // 1 except near the horizon, so A ≥ 0.99 for m ≤ 0.1.
  std::printf("directional albedo with F = 1 (rows m, columns view angle 0 30 60 80 deg)\n");
  for (const double m : {0.05, 0.1, 0.2, 0.4, 0.7}) {
    std::printf("  m = %.2f:", m);
    for (const double view_deg : {0.0, 30.0, 60.0, 80.0}) {
      const double a = directional_albedo(m, radians(view_deg));
      std::printf(" %.4f", a);
      EXPECT_LE(a, 1.0 + 2e-3) << "m = " << m << ", view " << view_deg << "°";
      EXPECT_GT(a, 0.3) << "m = " << m << ", view " << view_deg << "°";
      if (m <= 0.1 && view_deg == 0.0) {  // braces: EXPECT_* expands to an if/else
        EXPECT_GE(a, 0.99) << "m = " << m;
      }
    }
    std::printf("\n");
  }
}

TEST(CookTorrance, BrdfIsReciprocal) {
  const CookTorranceMaterial aluminium(aluminium_ior(), 0.15);
  const Material material = aluminium;
  for (int i = 0; i < 200; ++i) {
    // A deterministic spread of pairs of directions above the surface.
    const Vec3 l = from_spherical(0.01 + 1.5 * std::fmod(i * 0.618034, 1.0), 6.283 * std::fmod(i * 0.414214, 1.0));
    const Vec3 v = from_spherical(0.01 + 1.5 * std::fmod(i * 0.732051, 1.0), 6.283 * std::fmod(i * 0.236068, 1.0));
    const MicrofacetTerm a = cook_torrance_term(kNormal, l, v, 0.15), b = cook_torrance_term(kNormal, v, l, 0.15);
    EXPECT_NEAR(a.brdf_without_fresnel, b.brdf_without_fresnel, 1e-12 * std::max(1.0, a.brdf_without_fresnel));
    EXPECT_NEAR(a.cos_view_half, b.cos_view_half, 1e-12);
    const Spectrum fa = specular_brdf(material, kNormal, l, v), fb = specular_brdf(material, kNormal, v, l);
    for (int k = 0; k < Spectrum::size(); ++k) EXPECT_FLOAT_EQ(fa[k], fb[k]);
  }
}

TEST(CookTorrance, ZeroBelowTheHorizon) {
  const Vec3 up = from_spherical(0.3, 0), below = {0.5, 0, -0.2};
  EXPECT_EQ(cook_torrance_term(kNormal, below, up, 0.2).brdf_without_fresnel, 0.0);
  EXPECT_EQ(cook_torrance_term(kNormal, up, below, 0.2).brdf_without_fresnel, 0.0);
}

TEST(CookTorrance, PeaksInTheMirrorDirection) {
  const Vec3 v = from_spherical(radians(40), 0);
  const Vec3 mirror = mirror_direction(kNormal, v);
  const double peak = cook_torrance_term(kNormal, mirror, v, 0.1).brdf_without_fresnel * dot(kNormal, mirror);
  for (const double off : {0.02, 0.05, 0.1}) {
    const Vec3 l = from_spherical(radians(40) + off, kPi);
    EXPECT_LT(cook_torrance_term(kNormal, l, v, 0.1).brdf_without_fresnel * dot(kNormal, l), peak) << off;
  }
}

TEST(CookTorrance, LobeRadiusIsWhereDFallsToOneThousandthOfItsPeak) {
  for (const double m : {0.01, 0.1, 0.15, 0.3}) {
    const double alpha = beckmann_half_angle_at_1e3(m);
    EXPECT_NEAR(beckmann_distribution(std::cos(alpha), m) / beckmann_distribution(1.0, m), 1e-3, 1e-9) << m;
    const CookTorranceMaterial material(aluminium_ior(), m);
    EXPECT_DOUBLE_EQ(specular_lobe_radius(material), 2 * alpha);
    std::printf("m = %.2f: lobe radius %.3f rad (%.1f deg)\n", m, 2 * alpha, degrees(2 * alpha));
  }
}

}  // namespace
}  // namespace skylit
