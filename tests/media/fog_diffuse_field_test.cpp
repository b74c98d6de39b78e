// The fog's multiple-scattering field (media/fog_diffuse_field.h) against independent
// solutions: adding–doubling for a homogeneous slab under a uniform sky
// (tests/media/adding_doubling.h), the exact equilibrium of a conservative slab over a
// white ground, the conservation of energy, and the Legendre moments of known phase
// functions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "adding_doubling.h"
#include "skylit/atmosphere/phase_functions.h"
#include "skylit/core/angles.h"
#include "skylit/media/fog_diffuse_field.h"
#include "skylit/media/fog_phase.h"

namespace skylit {
namespace {

constexpr double kTop = 100;

FogSettings slab(double optical_depth, double scale_height_m, FogPhase phase, double g) {
  FogSettings fog;
  fog.density_at_ground = 1.0;
  fog.scale_height_m = scale_height_m;
  fog.bottom_altitude_m = 0;
  fog.top_altitude_m = kTop;
  fog.phase = phase;
  fog.asymmetry = g;
  // The settings' column from the bottom to the top for ρ0 = 1, then σ for the depth.
  const FogLayer unit(fog);
  fog.unit_density_extinction_per_m = optical_depth / unit.column(0, 1, 0, kTop);
  return fog;
}

FogLayerLighting uniform_sky(double radiance, double ground_albedo) {
  FogLayerLighting light;
  light.sky = [radiance](double, double) { return Spectrum(static_cast<float>(radiance)); };
  light.ground_albedo = ground_albedo;
  return light;
}

TEST(FogDiffuseField, LegendreMomentsOfKnownPhaseFunctions) {
  // HG's moments are g^l exactly; the droplet fit's χ1 is its mean cosine (Draine's
  // closed form). To 1e-6: the quadrature's panels resolve the 15 µm fit's 0.4° peak.
  const std::vector<double> hg = phase_legendre_moments([](double c) { return henyey_greenstein_phase(c, 0.9); }, 17);
  for (int l = 0; l < 17; ++l) EXPECT_NEAR(hg[static_cast<size_t>(l)], std::pow(0.9, l), 1e-6) << l;
  const DropletPhaseParameters p = DropletPhaseParameters::for_diameter(15);
  const std::vector<double> droplet = phase_legendre_moments([&p](double c) { return droplet_phase(c, p); }, 2);
  EXPECT_NEAR(droplet[0], 1.0, 1e-6);
  EXPECT_NEAR(droplet[1], droplet_phase_mean_cosine(p), 1e-6);
}

TEST(FogDiffuseField, MatchesAddingDoublingForAHomogeneousSlab) {
  // A Henyey–Greenstein slab (g = 0.85) of optical depth 1 and 8 under a uniform sky of
  // radiance 1, black ground: the radiance leaving the top and the bottom at the
  // reference's cosines within 1 % of the adding–doubling solution with 32 nodes. What
  // is left is the discretisation (8 streams, δ-M, depth levels): 0.3 % worst, measured
  // (at τ = 1, μ = 0.9, reflected); the exponential density (h0 = 20 m) is the same slab
  // in optical depth and must give the same numbers. τ 400 has the coarser levels deep
  // inside (fog_diffuse_field.cpp), where the light has diffused.
  for (double tau : {1.0, 8.0, 400.0}) {
    const testing::AddingDoubling reference(32, tau, 1.0, [](double c) { return henyey_greenstein_phase(c, 0.85); });
    for (double h0 : {std::numeric_limits<double>::infinity(), 20.0}) {
      const FogLayer layer(slab(tau, h0, FogPhase::henyey_greenstein, 0.85));
      const FogDiffuseField field(layer, uniform_sky(1.0, 0.0));
      for (int i : {6, 16, 26}) {
        const double mu = reference.cosines()[static_cast<size_t>(i)];
        EXPECT_NEAR(field.radiance(kTop, mu, 0.0)[10], reference.reflected(i), 0.01 * reference.reflected(i))
            << "τ " << tau << " h0 " << h0 << " μ " << mu;
        EXPECT_NEAR(field.radiance(0, -mu, 0.0)[10], reference.transmitted(i), 0.01 * reference.transmitted(i))
            << "τ " << tau << " h0 " << h0 << " μ " << mu;
      }
    }
  }
}

TEST(FogDiffuseField, ConservativeFogOverAWhiteGroundIsInEquilibriumWithTheSky) {
  // No absorption anywhere and a uniform sky: the exact solution is the sky's radiance in
  // every direction at every depth, and so is the light scattered. Thin and thick fogs.
  for (double tau : {0.1, 3.0, 30.0}) {
    const FogLayer layer(slab(tau, 10.0, FogPhase::droplet_fit, 0));
    const FogDiffuseField field(layer, uniform_sky(2.0, 1.0));
    for (double z : {0.0, 5.0, 30.0, 99.0})
      for (double up : {-1.0, -0.5, -0.05, 0.05, 0.3, 1.0}) {
        EXPECT_NEAR(field.radiance(z, up, 0.0)[0], 2.0, 2e-3) << tau << " " << z << " " << up;
        EXPECT_NEAR(field.scattered(z, up, 0.0)[0], 2.0, 2e-3) << tau << " " << z << " " << up;
      }
  }
}

TEST(FogDiffuseField, ConservesTheSunsEnergy) {
  // The sun at 30° on a conservative fog over a white ground, no sky: all the sunlight
  // that enters leaves the top again, so the diffuse flux leaving the top equals μ0·E0.
  // The flux is ∫ L μ dω from the output directions (the trapezoidal rule in μ² steps);
  // within 1 %. τ 3000 has the coarser levels deep inside (fog_diffuse_field.cpp).
  for (double tau : {1.0, 10.0, 30.0, 3000.0}) {
    const FogLayer layer(slab(tau, 10.0, FogPhase::droplet_fit, 0));
    FogLayerLighting light = uniform_sky(0.0, 1.0);
    light.sun_irradiance = Spectrum(1.0f);
    light.sun_cosine = 0.5;
    const FogDiffuseField field(layer, light);
    double flux = 0;
    constexpr int kSteps = 500, kAzimuths = 32;  // the field varies with azimuth: over the half circle
    for (int i = 0; i < kSteps; ++i) {
      const double mu = (i + 0.5) / kSteps;
      for (int j = 0; j < kAzimuths; ++j)
        flux += 2 * kPi * mu * field.radiance(kTop, mu, (j + 0.5) * kPi / kAzimuths)[0] / (kSteps * kAzimuths);
    }
    EXPECT_NEAR(flux, 0.5, 0.005) << "τ " << tau;
  }
}

}  // namespace
}  // namespace skylit

namespace skylit {
namespace {

TEST(FogDiffuseField, MatchesAddingDoublingForASharpForwardLobe) {
  // g = 0.95: δ-M takes f = 0.44 of the scattering as a spike. Optical depth 10; the
  // reference with 48 nodes (its μ-grid resolves the lobe's ~3° width near the poles).
  const testing::AddingDoubling reference(48, 10.0, 1.0, [](double c) { return henyey_greenstein_phase(c, 0.95); });
  const FogLayer layer(slab(10.0, std::numeric_limits<double>::infinity(), FogPhase::henyey_greenstein, 0.95));
  const FogDiffuseField field(layer, uniform_sky(1.0, 0.0));
  for (int i : {8, 24, 40}) {
    const double mu = reference.cosines()[static_cast<size_t>(i)];
    std::printf("[FogDiffuseField] g 0.95 μ %.3f: reflected %.4f (AD %.4f), transmitted %.4f (AD %.4f)\n", mu,
                field.radiance(kTop, mu, 0.0)[10], reference.reflected(i), field.radiance(0, -mu, 0.0)[10],
                reference.transmitted(i));
    EXPECT_NEAR(field.radiance(kTop, mu, 0.0)[10], reference.reflected(i), 0.03 * reference.reflected(i)) << mu;
    EXPECT_NEAR(field.radiance(0, -mu, 0.0)[10], reference.transmitted(i), 0.03 * reference.transmitted(i)) << mu;
  }
}

}  // namespace
}  // namespace skylit

namespace skylit {
namespace {

TEST(FogDiffuseField, FollowsTheSunsSingleScatteringInAzimuth) {
  // A thin Henyey–Greenstein slab (g = 0.5, optical depth 0.001, no sky, black ground)
  // under the sun at 30°: the light is scattered once, and the radiance leaving the top
  // and the bottom has the closed form
  //     up:   ω E0 p(Θ) μ0/(μ0 + μ)·(1 − e^{−τ(1/μ0 + 1/μ)})
  //     down: ω E0 p(Θ) μ0/(μ0 − μ)·(e^{−τ/μ0} − e^{−τ/μ}),
  // Θ the angle between the sunbeam and the direction, which depends on the azimuth: the
  // values at φ = 0 and 180° are 0.2–3.7 times the azimuthal mean. Within 1 %: twice scattered
  // light is ~0.1 % here, δ-M's truncation (f = 0.5^16) and the series' 16 terms of an HG
  // phase function of g = 0.5 leave less than 0.1 %.
  constexpr double kTau = 0.001, kG = 0.5, kMu0 = 0.5;
  const FogLayer layer(slab(kTau, std::numeric_limits<double>::infinity(), FogPhase::henyey_greenstein, kG));
  const double omega = layer.single_scattering_albedo();
  FogLayerLighting light = uniform_sky(0.0, 0.0);
  light.sun_irradiance = Spectrum(1.0f);
  light.sun_cosine = kMu0;
  const FogDiffuseField field(layer, light);
  const double s0 = std::sqrt(1 - kMu0 * kMu0);
  for (double mu : {0.3, 0.7, 0.95})
    for (double phi_deg : {0.0, 60.0, 120.0, 180.0}) {
      const double phi = phi_deg * kPi / 180, s = std::sqrt(1 - mu * mu);
      const double cos_up = -kMu0 * mu + s0 * s * std::cos(phi), cos_down = kMu0 * mu + s0 * s * std::cos(phi);
      const double up =
          omega * henyey_greenstein_phase(cos_up, kG) * kMu0 / (kMu0 + mu) * -std::expm1(-kTau * (1 / kMu0 + 1 / mu));
      const double down = omega * henyey_greenstein_phase(cos_down, kG) * kMu0 / (kMu0 - mu) *
                          (std::exp(-kTau / kMu0) - std::exp(-kTau / mu));
      EXPECT_NEAR(field.radiance(kTop, mu, phi)[10], up, 0.01 * up) << "up μ " << mu << " φ " << phi_deg;
      EXPECT_NEAR(field.radiance(0, -mu, phi)[10], down, 0.01 * down) << "down μ " << mu << " φ " << phi_deg;
    }
}

}  // namespace
}  // namespace skylit
