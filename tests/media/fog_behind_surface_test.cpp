// What a surface changes in the fog's light in front of it (media/fog_behind_surface.h)
// against a brute-force evaluation of the same integral: every direction of a dense grid
// about the surface's normal, the full phase function's moments from their own
// quadrature, the view integrated step by step, and the field read from the solved
// field itself (not the class's table of it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "fog_slab.h"
#include "skylit/core/angles.h"
#include "skylit/media/fog_behind_surface.h"
#include "skylit/media/fog_diffuse_field.h"

namespace skylit {
namespace {

struct Hidden {
  double gain, field, field_in_shadow;  // at 550 nm's bin
};

// ΔL's two parts by brute force: directions of travel ω on a grid of 0.5° × 1° cells about
// the normal (only ω·n > 0 come through the plane), the view in 400 steps.
Hidden brute_force(const FogLayer& layer, const FogDiffuseField& field, const Vec3& sunbeam, const Vec3& point,
                   const Vec3& normal, const Vec3& toward_viewer, double distance_m, int bin) {
  const double sigma = layer.unit_density_extinction_bins()[static_cast<size_t>(bin)] * layer.density(point.z);
  const double albedo = layer.single_scattering_albedo();
  const std::vector<double> chi = phase_legendre_moments([&](double c) { return layer.phase(c); }, 2);
  const double transport = (1 - albedo * chi[1]) * sigma;
  const double spike_free = 1 - field.forward_fraction();
  const double un = dot(toward_viewer, normal);
  const auto [t1, t2] = perpendicular_pair(normal);
  const Vec3 sun_h = normalize(Vec3{sunbeam.x, sunbeam.y, 0});
  const Vec3 side{-sun_h.y, sun_h.x, 0};
  constexpr int kPolar = 180, kAround = 360, kSteps = 400;
  Hidden out{0, 0, 0};
  for (int i = 0; i < kPolar; ++i) {
    const double theta = (i + 0.5) * 0.5 * kPi / kPolar;  // from the normal
    const double cell = std::sin(theta) * (0.5 * kPi / kPolar) * (2 * kPi / kAround);
    for (int j = 0; j < kAround; ++j) {
      const double phi = (j + 0.5) * 2 * kPi / kAround;
      const Vec3 omega = std::cos(theta) * normal + std::sin(theta) * (std::cos(phi) * t1 + std::sin(phi) * t2);
      const double a = un / dot(omega, normal);
      double along = 0;
      for (int k = 0; k < kSteps; ++k) {
        const double s = (k + 0.5) * distance_m / kSteps;  // before the surface
        along += std::exp(-sigma * (distance_m - s)) * std::exp(-transport * s * a) * distance_m / kSteps;
      }
      const double weight = albedo * sigma * spike_free * field.smooth_phase(dot(omega, toward_viewer)) * cell * along;
      const double azimuth = std::atan2(dot(omega, side), dot(omega, sun_h));
      out.gain += weight;
      const double light = weight * field.radiance(point.z, omega.z, azimuth)[bin];
      out.field += light;
      if (dot(omega, sunbeam) <= 0) out.field_in_shadow += light;
    }
  }
  return out;
}

TEST(FogBehindSurfaces, MatchesABruteForceIntegralOfTheHiddenLight) {
  // The droplets' fog of optical depth 3 over 100 m under a uniform sky and a sun 30° up
  // over a grey ground; a wall facing the viewer, one tilted up, and the ground, seen face
  // on and obliquely from 20 and 80 m. The class's 16 × 16 directions about the view and
  // its field table (4° × 5°) against the brute force: measured within 1.5 % (gain) and
  // 2.5 % (field); asserted within 3 % and 4 %.
  const FogLayer layer(testing::uniform_fog_slab(3.0, 100.0));
  FogLayerLighting light;
  light.sky = [](double mu, double) { return Spectrum(static_cast<float>(0.5 + mu)); };
  light.sun_irradiance = Spectrum(1.0f);
  light.sun_cosine = 0.5;
  light.ground_albedo = 0.3;
  const FogDiffuseField field(layer, light);
  const Vec3 sunbeam = normalize(Vec3{0.0, -std::sqrt(3.0), -1.0});  // travelling south, down 30°
  const FogBehindSurfaces behind(layer, field, sunbeam);
  struct Case {
    const char* name;
    Vec3 point, normal, toward_viewer;
    double distance_m;
  };
  const Vec3 wall{0, -1, 0}, tilted = normalize(Vec3{0, -1, 1});
  const std::vector<Case> cases{
      {"wall face on, 20 m", {0, 50, 20}, wall, wall, 20},
      {"wall face on, 80 m", {0, 50, 20}, wall, wall, 80},
      {"wall at 60°, 40 m", {0, 50, 20}, wall, normalize(Vec3{std::sqrt(3.0), -1, 0}), 40},
      {"tilted, 40 m", {0, 50, 20}, tilted, normalize(Vec3{0.3, -1, 0.4}), 40},
      {"ground at 10°, 40 m", {0, 50, 0.01}, {0, 0, 1}, normalize(Vec3{0, -1, std::tan(radians(10.0))}), 40},
  };
  for (const Case& c : cases) {
    int bin = 0;
    for (int b = 1; b < kSpectralBins; ++b)
      if (std::abs(kGrid.center_nm(b) - 550.0) < std::abs(kGrid.center_nm(bin) - 550.0)) bin = b;
    FogHiddenBehind fast = behind.at(c.point, c.normal, c.toward_viewer, c.distance_m, c.distance_m, 1e9);
    // Through the fog to the viewer (the caller's part: beyond kHiddenHeldDepth, as at
    // 80 m here, `at` holds part of it already).
    const float to_viewer = hidden_light_transmittance(Transmittance(static_cast<float>(
        std::exp(-layer.unit_density_extinction_bins()[static_cast<size_t>(bin)] * c.distance_m))))[bin];
    fast.gain *= to_viewer;
    fast.field *= to_viewer;
    fast.field_in_shadow *= to_viewer;
    const Hidden exact = brute_force(layer, field, sunbeam, c.point, c.normal, c.toward_viewer, c.distance_m, bin);
    std::printf("[Behind] %s: gain %.5f / %.5f, field %.5f / %.5f\n", c.name, fast.gain[bin], exact.gain,
                fast.field[bin], exact.field);
    EXPECT_NEAR(fast.gain[bin], exact.gain, 0.03 * exact.gain) << c.name;
    EXPECT_NEAR(fast.field[bin], exact.field, 0.04 * exact.field) << c.name;
    // Without the sun's side: a small part of the whole here; within 4 % of itself plus
    // 1 % of the whole.
    std::printf("[Behind]   in a shadow: field %.5f / %.5f\n", fast.field_in_shadow[bin], exact.field_in_shadow);
    EXPECT_NEAR(fast.field_in_shadow[bin], exact.field_in_shadow, 0.04 * exact.field_in_shadow + 0.01 * exact.field)
        << c.name;
  }
}

}  // namespace
}  // namespace skylit
