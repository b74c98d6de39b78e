// Every phase function the renderers scatter with integrates to one over the sphere and
// has the mean cosine its documentation states (a quadrature graded toward θ = 0, where
// the forward peaks are), and the phase-function sampler of the path-traced reference
// draws directions that follow it (a χ² test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/phase_functions.h"
#include "skylit/clouds/cloud_scattering.h"
#include "skylit/core/counter_random.h"
#include "skylit/media/fog_phase.h"
#include "skylit/media/phase_sampler.h"

namespace skylit {
namespace {

struct Moments {
  double integral, mean_cosine;
};

// ∫ F dΩ and ∫ F cos θ dΩ by Simpson's rule on θ = π t³, 30,000 intervals in t.
Moments moments(const std::function<double(double)>& phase) {
  constexpr int kIntervals = 30000;
  auto f = [&](double t, double weight_cos) {
    const double theta = kPi * t * t * t, dtheta_dt = 3 * kPi * t * t;
    const double c = std::cos(theta);
    return phase(c) * 2 * kPi * std::sin(theta) * dtheta_dt * (weight_cos ? c : 1.0);
  };
  Moments m{0, 0};
  const double h = 1.0 / kIntervals;
  for (int i = 0; i < kIntervals; ++i) {
    const double a = i * h, b = a + h, mid = a + h / 2;
    m.integral += h / 6 * (f(a, 0) + 4 * f(mid, 0) + f(b, 0));
    m.mean_cosine += h / 6 * (f(a, 1) + 4 * f(mid, 1) + f(b, 1));
  }
  return m;
}

struct Case {
  std::string name;
  std::function<double(double)> phase;
  double stated_mean_cosine;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (double gamma : {0.0, 0.0140})
    out.push_back({"Rayleigh", [=](double c) { return rayleigh_phase(c, gamma); }, 0.0});
  for (double g : {0.0, 0.5, 0.85, 0.99})
    out.push_back({"Henyey-Greenstein", [=](double c) { return henyey_greenstein_phase(c, g); }, g});
  // Cornette–Shanks: the parameter g is not the mean cosine, which is 3g(4 + g²)/(5(2 + g²))
  // (Cornette & Shanks 1992): 0.80 for g = 0.75.
  for (double g : {0.5, 0.75})
    out.push_back({"Cornette-Shanks", [=](double c) { return cornette_shanks_phase(c, g); },
                   3 * g * (4 + g * g) / (5 * (2 + g * g))});
  for (double d : {5.0, 15.0, 50.0}) {
    const DropletPhaseParameters p = DropletPhaseParameters::for_diameter(d);
    out.push_back({"fog droplets", [=](double c) { return droplet_phase(c, p); }, droplet_phase_mean_cosine(p)});
  }
  out.push_back({"cloud droplets", [](double c) { return cloud_phase(c); }, cloud_mean_cosine()});
  return out;
}

// The aerosol types' phase functions: the mean cosine stated is OPAC's asymmetry
// parameter of each type (data/aerosol_types.csv), for both shapes. (Not sampled by
// PhaseSampler: the sky is not path traced through the air; the shapes themselves are
// in cases().)
std::vector<Case> aerosol_cases() {
  std::vector<Case> out;
  for (const std::string_view name : aerosol_type_names())
    for (AerosolPhase shape : {AerosolPhase::cornette_shanks, AerosolPhase::henyey_greenstein}) {
      AerosolSettings aerosol = with_aerosol_type({}, *aerosol_type_from_name(name));
      aerosol.phase = shape;
      out.push_back({"aerosol " + std::string(name), [=](double c) { return AerosolPhaseFunction(aerosol)(c); },
                     aerosol.asymmetry});
    }
  return out;
}

TEST(PhaseFunctions, IntegrateToOneWithTheStatedMeanCosine) {
  std::vector<Case> all = cases();
  for (Case& c : aerosol_cases()) all.push_back(std::move(c));
  for (const Case& c : all) {
    const Moments m = moments(c.phase);
    EXPECT_NEAR(m.integral, 1.0, 1e-6) << c.name;
    EXPECT_NEAR(m.mean_cosine, c.stated_mean_cosine, 1e-6) << c.name;
  }
}

TEST(PhaseSampler, DirectionsFollowThePhaseFunction) {
  // 200,000 directions binned in 100 rings of equal probability under the phase
  // function itself (cut at quantiles found by the same graded quadrature): each ring
  // expects 2,000; χ² over 99 degrees of freedom below 160 (p ≈ 1e-4).
  for (const Case& c : cases()) {
    const PhaseSampler sampler(c.phase);
    constexpr int kRings = 100, kSamples = 200000;
    // The ring edges as cosines: walk the cumulative distribution from θ = 0.
    std::vector<double> edge_cos{1.0};
    {
      constexpr int kSteps = 200000;
      double cumulative = 0;
      double previous_theta = 0;
      for (int i = 1; i <= kSteps && static_cast<int>(edge_cos.size()) < kRings; ++i) {
        const double t = static_cast<double>(i) / kSteps, theta = kPi * t * t * t;
        const double mid = 0.5 * (theta + previous_theta);
        cumulative += c.phase(std::cos(mid)) * 2 * kPi * std::sin(mid) * (theta - previous_theta);
        previous_theta = theta;
        if (cumulative >= static_cast<double>(edge_cos.size()) / kRings) edge_cos.push_back(std::cos(theta));
      }
      while (static_cast<int>(edge_cos.size()) < kRings) edge_cos.push_back(-1.0);
      edge_cos.push_back(-1.0 - 1e-12);
    }
    std::vector<int> counts(kRings, 0);
    const Vec3 forward = normalize(Vec3{0.3, -0.4, 0.8});
    for (int i = 0; i < kSamples; ++i) {
      CounterRandom random(21, 0, static_cast<uint64_t>(i));
      const double u1 = random.uniform(), u2 = random.uniform();
      const double cos_theta = dot(forward, sampler.sample(forward, u1, u2).direction);
      int ring = 0;
      while (ring < kRings - 1 && cos_theta < edge_cos[static_cast<size_t>(ring + 1)]) ++ring;
      ++counts[static_cast<size_t>(ring)];
    }
    double chi2 = 0;
    for (int n : counts) chi2 += (n - 2000.0) * (n - 2000.0) / 2000.0;
    EXPECT_LT(chi2, 160) << c.name;
  }
}

TEST(PhaseSampler, ConeDrawsStayInTheConeAndWeighToItsProbability) {
  // The path tracer's spike strategy (render/path_integrator.h) draws within a forward
  // cone: every draw inside it, the density stated at the draw the one pdf_within gives
  // for its direction, and phase / density averaging to the phase function's integral
  // over the cone's rings, here by the graded quadrature of the test above (to 4 standard
  // errors of 20,000 draws, and 1e-3 for the table's own probability).
  for (const Case& c : cases()) {
    const PhaseSampler sampler(c.phase);
    const PhaseSampler::Cone cone = sampler.cone(radians(5.0));
    ASSERT_GT(cone.probability, 0.0) << c.name;
    double quadrature = 0;
    {
      constexpr int kSteps = 200000;
      const double edge = std::acos(cone.min_cos);
      for (int i = 0; i < kSteps; ++i) {
        const double a = edge * std::pow(static_cast<double>(i) / kSteps, 3);
        const double b = edge * std::pow(static_cast<double>(i + 1) / kSteps, 3), mid = 0.5 * (a + b);
        quadrature += c.phase(std::cos(mid)) * 2 * kPi * std::sin(mid) * (b - a);
      }
    }
    EXPECT_NEAR(cone.probability, quadrature, 1e-3 * quadrature + 1e-9) << c.name;
    const Vec3 forward = normalize(Vec3{-0.2, 0.5, 0.7});
    constexpr int kSamples = 20000;
    double sum = 0, squares = 0;
    int mismatched = 0;
    for (int i = 0; i < kSamples; ++i) {
      CounterRandom random(22, 0, static_cast<uint64_t>(i));
      const double u1 = random.uniform(), u2 = random.uniform();
      const PhaseSampler::Sample s = sampler.sample_within(cone, forward, u1, u2);
      const double cos_theta = dot(forward, s.direction);
      ASSERT_GE(cos_theta, cone.min_cos - 1e-9) << c.name;
      if (std::abs(sampler.pdf_within(cone, cos_theta) / s.pdf - 1) > 1e-9) ++mismatched;
      const double w = c.phase(cos_theta) / s.pdf;
      sum += w;
      squares += w * w;
    }
    const double mean = sum / kSamples;
    const double error = std::sqrt(std::max(0.0, squares / kSamples - mean * mean) / kSamples);
    EXPECT_NEAR(mean, quadrature, 4 * error + 1e-3 * quadrature) << c.name;
    // Directions on a ring's edge may round into the next ring: a few in 10,000.
    EXPECT_LT(mismatched, kSamples / 1000) << c.name;
    EXPECT_EQ(sampler.pdf_within(cone, std::cos(radians(30.0))), 0.0) << c.name;
  }
}

}  // namespace
}  // namespace skylit
