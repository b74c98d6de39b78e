// A lamp's light scattered by fog (media/lamp_in_scatter.h): against the closed form of
// Sun et al. (2005) for an isotropic lamp in a homogeneous, isotropically scattering
// medium, against the elementary closed form without extinction, against adaptive
// quadrature of the definition in s for a spot lamp and the droplet phase function,
// and the emission cone's clipping against point tests.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../reference_quadrature.h"
#include "skylit/lights/lamp_spectrum.h"
#include "skylit/media/lamp_in_scatter.h"

namespace skylit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A homogeneous, isotropically scattering fog of extinction sigma (m⁻¹) from the
// ground to 1 km.
FogSettings homogeneous_fog(double sigma) {
  FogSettings s;
  s.density_at_ground = 1.0;
  s.unit_density_extinction_per_m = sigma;
  s.scale_height_m = kInf;
  s.bottom_altitude_m = 0.0;
  s.top_altitude_m = 1000.0;
  s.phase = FogPhase::henyey_greenstein;
  s.asymmetry = 0.0;
  return s;
}

// A flat spectrum of one unit per candela, so the result is the scalar integral.
const Spectrum kUnit(1.0f);

// Sun et al. 2005, Eq. 6 for an infinite ray: with the lamp at distance h from the
// ray and its foot at s0 ahead of the viewer, s + r = s0 + h tan(θ/2), so
//   L = σ I e^{−σ s0} / (2π h) · [F(σh, π/2) − F(σh, θ0/2)],  F(u, v) = ∫₀^v e^{−u tan ξ} dξ,
// θ0 = atan2(h, s0); F by adaptive Gauss–Kronrod.
double sun_et_al(double sigma, double intensity, double h, double s0) {
  const double theta0 = std::atan2(h, s0);
  const double f = testing::integrate([&](double xi) { return std::exp(-sigma * h * std::tan(xi)); }, theta0 / 2,
                                      kPi / 2 - 1e-12, 1e-12);
  return sigma * intensity * std::exp(-sigma * s0) / (2 * kPi * h) * f;
}

TEST(LampInScatter, IsotropicLampInHomogeneousFogMatchesSunEtAlClosedForm) {
  // The glow around a lamp seen at increasing angles: falls off as the closed form,
  // for a lamp ahead of the viewer and one behind it (whose light reaches the viewer
  // scattered backward, from the far tail of the ray, near θ = π). Tolerance 1e-4:
  // three-point Gauss–Legendre panels graded toward the forward peak and, where the
  // ray runs on for more than an optical depth beyond the lamp, toward θ = π; measured
  // ≤ 2e-5.
  const FogLayer layer(homogeneous_fog(0.01));
  for (double foot : {30.0, -10.0}) {
    const Luminaire lamp({0, foot, 10}, IntensityDistribution::isotropic(1000.0));
    const LampInScatter glow(layer, lamp, kUnit);
    for (double offset : {0.1, 0.5, 2.0, 5.0, 15.0, 40.0, 120.0}) {
      // The viewer at y = 0, 'offset' metres to the side of the lamp's line.
      const Ray ray{{offset, 0, 10}, {0, 1, 0}};
      const double expected = sun_et_al(0.01, 1000.0, offset, foot);
      const double got = glow.along(ray, {{0.0, kInf}})[7];
      EXPECT_NEAR(got, expected, 1e-4 * expected) << "foot " << foot << " offset " << offset;
    }
  }
}

TEST(LampInScatter, WithoutExtinctionMatchesElementaryClosedForm) {
  // σ → 0 (scattering kept by normalising): L/σ = I (θ1 − θ0)/(4π h) over a finite ray
  // [0, D], θ = atan2(h, s0 − s); exact to rounding, tolerance 1e-6.
  const double sigma = 1e-9;
  const FogLayer layer(homogeneous_fog(sigma));
  const Luminaire lamp({3, 20, 5}, IntensityDistribution::isotropic(500.0));
  const LampInScatter glow(layer, lamp, kUnit);
  const Ray ray{{0, 0, 5}, {0, 1, 0}};
  for (double distance : {5.0, 20.0, 60.0}) {
    const double expected = 500.0 * (std::atan2(3.0, 20.0 - distance) - std::atan2(3.0, 20.0)) / (4 * kPi * 3.0);
    EXPECT_NEAR(glow.along(ray, {{0.0, distance}})[0] / sigma, expected, 1e-6 * expected) << distance;
  }
}

TEST(LampInScatter, SpotLampWithDropletPhaseMatchesQuadratureOfDefinition) {
  // A headlight-like spot (inner 8°, outer 15°) aimed along +x, seen by rays across and
  // along its beam, in a fog thinning upward with the droplet phase function: against
  // adaptive quadrature of the definition in s (tolerance 5e-3: the spot's smoothstep
  // edge inside a panel).
  FogSettings settings;
  settings.density_at_ground = 1.0;
  settings.unit_density_extinction_per_m = 0.02;
  settings.scale_height_m = 30.0;
  settings.top_altitude_m = 100.0;
  const FogLayer layer(settings);
  const Luminaire lamp({0, 0, 0.7}, IntensityDistribution::spot(20000.0, 8.0, 15.0), {1, 0, 0});
  const LampInScatter glow(layer, lamp, kUnit);
  for (const Ray& ray :
       {Ray{{20, -15, 1.5}, normalize(Vec3{0, 1, 0})}, Ray{{30, -10, 1.2}, normalize(Vec3{-0.3, 1, 0.05})},
        Ray{{-5, 1, 1.5}, normalize(Vec3{1, 0.02, -0.01})}}) {
    auto integrand = [&](double s) {
      const Vec3 p = ray.origin + s * ray.direction;
      const Vec3 to_p = p - lamp.position();
      const double r2 = dot(to_p, to_p);
      const double cos_theta = -dot(to_p, ray.direction) / std::sqrt(r2);
      const double column =
          layer.column(ray.origin.z, ray.direction.z, 0, s) + layer.column_between(lamp.position(), p);
      return layer.density(p.z) * 0.02 * lamp.intensity(to_p) / r2 * layer.phase(cos_theta) * std::exp(-0.02 * column);
    };
    double expected = 0;
    for (double a = 0; a < 400; a += 2) expected += testing::integrate(integrand, a, a + 2, 1e-8);
    const double got = glow.along(ray, {{0.0, 400.0}})[0];
    ASSERT_GT(expected, 0);
    EXPECT_NEAR(got, expected, 5e-3 * expected);
  }
}

TEST(LampInScatter, ShadowedPartAddsNothing) {
  // Splitting the lit range: the parts add up to the whole, within the quadrature's
  // error (1e-3), and an empty lit set gives exactly 0.
  const FogLayer layer(homogeneous_fog(0.01));
  const Luminaire lamp({0, 30, 10}, IntensityDistribution::isotropic(1000.0));
  const LampInScatter glow(layer, lamp, kUnit);
  const Ray ray{{2, 0, 10}, {0, 1, 0}};
  const double whole = glow.along(ray, {{0, 100}})[0];
  const double parts = glow.along(ray, {{0, 25}})[0] + glow.along(ray, {{25, 40}})[0] + glow.along(ray, {{40, 100}})[0];
  EXPECT_NEAR(parts, whole, 1e-3 * whole);
  EXPECT_EQ(glow.along(ray, {})[0], 0.0f);
}

TEST(LampInScatter, EmittingIntervalsAgreeWithPointTests) {
  const FogLayer layer(homogeneous_fog(0.01));
  for (double outer : {10.0, 60.0, 90.0, 120.0}) {
    const Luminaire lamp({0, 0, 5}, IntensityDistribution::spot(1.0, outer, outer), normalize(Vec3{0.3, 0.2, -1}));
    const LampInScatter glow(layer, lamp, kUnit);
    for (const Ray& ray : {Ray{{-20, 3, 1}, normalize(Vec3{1, 0, 0})}, Ray{{0, -30, 1}, normalize(Vec3{0.1, 1, 0.2})},
                           Ray{{4, 4, 20}, normalize(Vec3{-0.2, -0.1, -1})}}) {
      std::vector<Interval> in;
      glow.emitting_intervals(ray, 0, 80, in);
      for (double s = 0.01; s < 80; s += 0.173) {
        const Vec3 v = ray.origin + s * ray.direction - lamp.position();
        const double gamma = std::acos(std::clamp(dot(normalize(v), lamp.aim()), -1.0, 1.0)) * 180 / kPi;
        if (std::abs(gamma - outer) < 0.05) continue;  // on the cone's surface
        bool covered = false;
        for (const Interval& i : in) covered = covered || (s >= i.begin && s <= i.end);
        EXPECT_EQ(covered, gamma < outer) << "outer " << outer << " s " << s;
      }
    }
  }
}

}  // namespace
}  // namespace skylit
