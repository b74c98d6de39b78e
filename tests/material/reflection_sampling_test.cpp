// Sampling of the materials' reflection (material/reflection_sampling.h) against its
// own evaluation: a χ² test of where the directions land against the density, and the
// mean weight against the directional albedo by quadrature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "skylit/core/counter_random.h"
#include "skylit/material/optical_constants.h"
#include "skylit/material/reflection.h"
#include "skylit/material/reflection_sampling.h"

namespace skylit {
namespace {

struct Case {
  std::string name;
  Material material;
};

std::vector<Case> materials() {
  return {{"diffuse", DiffuseMaterial{Spectrum(0.5f)}},
          {"aluminium m=0.1", CookTorranceMaterial(aluminium_ior(), 0.1)},
          {"aluminium m=0.3", CookTorranceMaterial(aluminium_ior(), 0.3)},
          {"coated m=0.15", CookTorranceMaterial(constant_ior(1.5), 0.15, Spectrum(0.6f))},
          {"smooth coat", CookTorranceMaterial(constant_ior(1.5), 0.0, Spectrum(0.6f))},
          {"glass", GlassMaterial(soda_lime_glass_ior(), 0.006, 0.0, Spectrum(0.3f))}};
}

// The view directions: θ_v with cos 0.95, 0.5 and 0.15 in the x–z plane, n = z.
std::vector<Vec3> views() {
  std::vector<Vec3> out;
  for (double c : {0.95, 0.5, 0.15}) out.push_back({std::sqrt(1 - c * c), 0, c});
  return out;
}

constexpr Vec3 kNormal{0, 0, 1};

// The upper tail of the χ² distribution with k degrees of freedom at x, by the
// Wilson–Hilferty cube-root normal approximation (accurate to a few per cent of p for
// k ≥ 30, far finer than the 1e-4 threshold needs).
double chi2_upper_tail(double x, double k) {
  const double s = 2.0 / (9.0 * k);
  const double z = (std::cbrt(x / k) - (1 - s)) / std::sqrt(s);
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

TEST(ReflectionSampling, DirectionsFollowTheStatedDensity) {
  // 64 × 128 bins in (θ, φ) over the hemisphere; expected counts from the density
  // integrated over each bin by a 4 × 4 midpoint rule; bins expecting fewer than 5
  // samples pooled. A sampler that draws from another density than reflection_pdf
  // states (or the mirror lobe's share wrong) fails at p < 1e-4.
  constexpr int kTheta = 64, kPhi = 128, kSamples = 400000, kSub = 4;
  for (const Case& c : materials()) {
    for (const Vec3& v : views()) {
      std::vector<double> observed(kTheta * kPhi, 0.0), expected(kTheta * kPhi, 0.0);
      for (int i = 0; i < kSamples; ++i) {
        CounterRandom random(7, static_cast<uint64_t>(i), 0);
        const double u0 = random.uniform(), u1 = random.uniform(), u2 = random.uniform();
        const auto s = sample_reflection(c.material, kNormal, v, u0, u1, u2);
        if (!s || s->mirror || s->to_light.z <= 0) continue;
        const double theta = std::acos(std::clamp(s->to_light.z, -1.0, 1.0));
        double phi = std::atan2(s->to_light.y, s->to_light.x);
        if (phi < 0) phi += 2 * kPi;
        const int ti = std::min(kTheta - 1, static_cast<int>(theta / (kPi / 2) * kTheta));
        const int pi = std::min(kPhi - 1, static_cast<int>(phi / (2 * kPi) * kPhi));
        observed[static_cast<size_t>(ti * kPhi + pi)] += 1;
      }
      const double dt = kPi / 2 / kTheta, dp = 2 * kPi / kPhi;
      for (int ti = 0; ti < kTheta; ++ti)
        for (int pi = 0; pi < kPhi; ++pi) {
          double integral = 0;
          for (int a = 0; a < kSub; ++a)
            for (int b = 0; b < kSub; ++b) {
              const double theta = (ti + (a + 0.5) / kSub) * dt, phi = (pi + (b + 0.5) / kSub) * dp;
              const Vec3 l{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
              integral += reflection_pdf(c.material, kNormal, l, v) * std::sin(theta) * dt * dp / (kSub * kSub);
            }
          expected[static_cast<size_t>(ti * kPhi + pi)] = integral * kSamples;
        }
      double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
      int bins = 0;
      for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5) {
          pooled_observed += observed[i];
          pooled_expected += expected[i];
          continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++bins;
      }
      if (pooled_expected >= 5) {
        chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
        ++bins;
      }
      if (bins < 2) continue;  // all in the mirror (nothing else to test)
      const double p = chi2_upper_tail(chi2, bins - 1);
      EXPECT_GT(p, 1e-4) << c.name << ", view cos " << v.z << ": χ² " << chi2 << " over " << bins << " bins";
    }
  }
}

TEST(ReflectionSampling, MeanWeightIsTheDirectionalAlbedo) {
  // E[weight] over the non-mirror lobes equals ∫ f (n·l) dω (quadrature: 512 × 1024
  // midpoint over the hemisphere), and the mirror's share equals its reflectance; within
  // three standard errors of 200,000 samples plus 0.3 % for the quadrature (the m = 0.1
  // lobe is 0.1 rad wide: 60 quadrature cells across it).
  constexpr int kSamples = 200000;
  for (const Case& c : materials()) {
    for (const Vec3& v : views()) {
      double sum = 0, sum2 = 0, mirror_sum = 0;
      for (int i = 0; i < kSamples; ++i) {
        CounterRandom random(11, static_cast<uint64_t>(i), 0);
        const double u0 = random.uniform(), u1 = random.uniform(), u2 = random.uniform();
        const auto s = sample_reflection(c.material, kNormal, v, u0, u1, u2);
        if (!s) continue;
        const double w = s->weight[20];
        if (s->mirror) {
          mirror_sum += w;
          continue;
        }
        sum += w;
        sum2 += w * w;
      }
      const double mean = sum / kSamples, sigma = std::sqrt(std::max(0.0, sum2 / kSamples - mean * mean) / kSamples);
      constexpr int kTheta = 512, kPhi = 1024;
      double albedo = 0;
      for (int ti = 0; ti < kTheta; ++ti)
        for (int pi = 0; pi < kPhi; ++pi) {
          const double theta = (ti + 0.5) * (kPi / 2) / kTheta, phi = (pi + 0.5) * 2 * kPi / kPhi;
          const Vec3 l{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
          albedo += reflection_cos(c.material, kNormal, l, v).per_sr[20] * std::sin(theta) * (kPi / 2 / kTheta) *
                    (2 * kPi / kPhi);
        }
      EXPECT_NEAR(mean, albedo, 3 * sigma + 3e-3 * albedo + 1e-9) << c.name << ", view cos " << v.z;
      const std::optional<Reflectance> mirror = mirror_reflectance(c.material, kNormal, v);
      const double mirror_expected = mirror ? (*mirror)[20] : 0.0;
      EXPECT_NEAR(mirror_sum / kSamples, mirror_expected, 0.02 * mirror_expected + 1e-9) << c.name << " mirror";
    }
  }
}

}  // namespace
}  // namespace skylit
