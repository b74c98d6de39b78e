// What the renderer asks of materials (reflection.h): diffuse albedos, the specular
// lobe with spectral Fresnel, mirrors, and energy conservation of the layered model.
#include "skylit/material/reflection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skylit/material/fresnel.h"

namespace skylit {
namespace {

const Vec3 kNormal{0, 0, 1};

Vec3 from_spherical(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

double mean(const Spectrum& s) {
  double sum = 0;
  for (int i = 0; i < Spectrum::size(); ++i) sum += s[i];
  return sum / Spectrum::size();
}

// ∫ specular_reflection dω_l per bin, over half vectors (see cook_torrance_test.cpp).
Spectrum specular_albedo(const Material& material, double view_theta) {
  const Vec3 v = from_spherical(view_theta, 0);
  const int n_theta = 1500, n_phi = 180;
  const double d_theta = (kPi / 2) / n_theta, d_phi = 2 * kPi / n_phi;
  Spectrum sum;
  for (int i = 0; i < n_theta; ++i) {
    const double theta = (i + 0.5) * d_theta;
    for (int j = 0; j < n_phi; ++j) {
      const Vec3 h = from_spherical(theta, (j + 0.5) * d_phi);
      const double vh = dot(v, h);
      if (vh <= 0) continue;
      const Vec3 l = 2 * vh * h - v;
      sum += specular_reflection(material, kNormal, l, v).per_sr *
             static_cast<float>(4 * vh * std::sin(theta) * d_theta * d_phi);
    }
  }
  return sum;
}

TEST(Material, DiffuseIsLambertianOnly) {
  const Material m = DiffuseMaterial{Spectrum(0.3f)};
  EXPECT_FLOAT_EQ(diffuse_albedo(m, 0.2)[5], 0.3f);
  EXPECT_FALSE(has_specular(m));
  EXPECT_FALSE(mirror_reflectance(m, kNormal, kNormal).has_value());
  EXPECT_TRUE(specular_reflection(m, kNormal, kNormal, kNormal).per_sr.is_black());
  EXPECT_EQ(specular_lobe_radius(m), 0.0);
}

TEST(Material, AluminiumIsPracticallyOnlySpecular) {
  const Material m = CookTorranceMaterial(aluminium_ior(), 0.15);
  EXPECT_TRUE(diffuse_albedo(m, 1.0).is_black());
  EXPECT_TRUE(has_specular(m));
  EXPECT_FALSE(mirror_reflectance(m, kNormal, kNormal).has_value());
  // Seen head-on it reflects about 0.9 of a uniform sky: F ≈ 0.92 and small G losses.
  const double a = mean(specular_albedo(m, 0.0));
  EXPECT_GT(a, 0.88);
  EXPECT_LT(a, 0.93);
}

TEST(Material, SpecularWeightIsTheBinMeanOfSpecularReflection) {
  const Material m = CookTorranceMaterial(aluminium_ior(), 0.15);
  for (int i = 0; i < 50; ++i) {
    const Vec3 l = from_spherical(1.5 * std::fmod(i * 0.618034, 1.0), 6.283 * std::fmod(i * 0.414214, 1.0));
    const Vec3 v = from_spherical(1.5 * std::fmod(i * 0.732051, 1.0), 0.3);
    const double expected = mean(specular_reflection(m, kNormal, l, v).per_sr);
    EXPECT_NEAR(specular_weight(m, kNormal, l, v), expected, 1e-5 * std::max(1.0, expected));
  }
}

TEST(Material, SpecularReflectionIsBrdfTimesCosine) {
  const Material m = CookTorranceMaterial(constant_ior(1.5), 0.2, Spectrum(0.5f));
  const Vec3 l = from_spherical(0.7, 0.2), v = from_spherical(0.5, 3.0);
  EXPECT_NEAR(specular_reflection(m, kNormal, l, v).per_sr[3], specular_brdf(m, kNormal, l, v)[3] * std::cos(0.7),
              1e-6);
  EXPECT_TRUE(specular_reflection(m, kNormal, {0.3, 0, -0.9539}, v).per_sr.is_black());
}

TEST(Material, LayeredWhiteBaseUnderSmoothCoatConservesEnergyExactly) {
  // A white body (A = 1 − F(0) = 0.96) under a smooth coat: the diffuse albedo is
  // what the coat does not reflect.
  const CookTorranceMaterial coat(constant_ior(1.5), 0.0, Spectrum(0.96f));
  const Material m = coat;
  ASSERT_TRUE(coat.is_mirror());
  for (const double c : {1.0, 0.7, 0.3, 0.05}) {
    const auto mirror = mirror_reflectance(m, kNormal, from_spherical(std::acos(c), 0));
    ASSERT_TRUE(mirror.has_value());
    EXPECT_NEAR((*mirror)[0], fresnel_reflectance(c, 1.5), 1e-4);  // the table's error
    EXPECT_NEAR(diffuse_albedo(m, c)[0] + (*mirror)[0], 1.0, 1e-4) << c;
  }
}

TEST(Material, LayeredUnderRoughCoatReflectsAtMostWhatItReceives) {
  // A white body under a rough coat: specular lobe + diffuse ≈ 1. Not exactly: the
  // diffuse factor 1 − F(θ_v) is the smooth coat's, while the lobe's Fresnel is taken
  // at v·h, which for oblique views is slightly larger (measured: at most +0.22 %, m = 0.2 at
  // 45°), and G takes light away at grazing views. Tolerance: ≤ 1.005; ≥ 0.75 (G's
  // loss: 0.797 at m = 0.4, 80°). Grey bases reflect less. Printed for docs/materials.md.
  for (const double m : {0.1, 0.2, 0.3, 0.4}) {
    const Material layered = CookTorranceMaterial(constant_ior(1.5), m, Spectrum(0.96f));
    for (const double view_deg : {0.0, 30.0, 45.0, 60.0, 80.0}) {
      const double spec = specular_albedo(layered, radians(view_deg))[0];
      const double diff = diffuse_albedo(layered, std::cos(radians(view_deg)))[0];
      std::printf("m = %.1f, view %2.0f deg: specular %.4f + diffuse %.4f = %.4f\n", m, view_deg, spec, diff,
                  spec + diff);
      EXPECT_LE(spec + diff, 1.005) << m << " " << view_deg;
      EXPECT_GT(spec + diff, 0.75) << m << " " << view_deg;
    }
  }
}

TEST(Material, DiffuseReflectanceIsWhatIsSeenHeadOn) {
  // A = 0.5 under n = 1.5: 0.5 at normal view, 0.5 (1 − F(60°)) / (1 − F(0)) =
  // 0.5 × 0.91077 / 0.96 = 0.47436 at 60°.
  const Material m = CookTorranceMaterial(constant_ior(1.5), 0.2, Spectrum(0.5f));
  EXPECT_NEAR(diffuse_albedo(m, 1.0)[0], 0.5, 1e-5);
  EXPECT_NEAR(diffuse_albedo(m, 0.5)[0], 0.47436, 2e-4);
  // More than a white body under the coat can give is taken as that: 1 − F(0).
  const Material too_bright = CookTorranceMaterial(constant_ior(1.5), 0.2, Spectrum(0.99f));
  EXPECT_NEAR(diffuse_albedo(too_bright, 1.0)[0], 0.96, 1e-5);
}

TEST(Material, ConductorWithDiffuseBaseIsRejected) {
  EXPECT_THROW(CookTorranceMaterial(aluminium_ior(), 0.1, Spectrum(0.5f)), std::invalid_argument);
}

TEST(Material, GlassIsAMirrorWithTheDarkRoomBehind) {
  const Material m = GlassMaterial(soda_lime_glass_ior(), 0.006, 0.0, Spectrum(0.05f));
  EXPECT_FALSE(has_specular(m));
  EXPECT_EQ(specular_lobe_radius(m), 0.0);
  const auto normal = mirror_reflectance(m, kNormal, kNormal);
  ASSERT_TRUE(normal.has_value());
  EXPECT_NEAR((*normal)[17], 0.08, 0.005);  // two surfaces, 4 % each
  const auto grazing = mirror_reflectance(m, kNormal, from_spherical(radians(85), 0));
  EXPECT_GT((*grazing)[17], 0.5);
  // The room: 0.05 × T̄ (≈ 0.80) × T(0°) (≈ 0.89).
  const double room = diffuse_albedo(m, 1.0)[17];
  EXPECT_NEAR(room, 0.05 * 0.80 * 0.89, 0.003);
  EXPECT_LT(diffuse_albedo(m, 0.1)[17], room);
  EXPECT_FALSE(mirror_reflectance(m, kNormal, {0, 0.3, -1}).has_value());
}

TEST(Material, RoughGlassHasALobeInsteadOfAMirror) {
  const Material m = GlassMaterial(soda_lime_glass_ior(), 0.006, 0.02, Spectrum(0.05f));
  EXPECT_TRUE(has_specular(m));
  EXPECT_FALSE(mirror_reflectance(m, kNormal, kNormal).has_value());
  EXPECT_NEAR(mean(specular_albedo(m, 0.0)), 0.08, 0.01);
}

}  // namespace
}  // namespace skylit
