// Sky light in fog (Eqs. 13–14): the table J(z) against direct quadratures of the sky,
// and the adaptive trapezoidal integration along view rays against a fine fixed-step one.
#include "skylit/media/fog_sky_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

namespace skylit {
namespace {

const SkyModel& test_sky() {
  static const Atmosphere atmosphere{AtmosphereSettings{}};
  static const SkyModel sky{atmosphere, direction_from_altitude_azimuth(40, 150), 1.6};
  return sky;
}

double bin_mean(const Spectrum& s) {
  double sum = 0;
  for (int i = 0; i < kSpectralBins; ++i) sum += s[i];
  return sum / kSpectralBins;
}

double worst_relative(const Spectrum& got, const std::array<double, kSpectralBins>& want) {
  double worst = 0;
  for (int i = 0; i < kSpectralBins; ++i)
    worst = std::max(worst, std::abs(got[i] - want[static_cast<size_t>(i)]) / std::abs(want[static_cast<size_t>(i)]));
  return worst;
}

// ∫ L e^(−σ V/|w|) dω by a fine product rule: w = ±u², u midpoints (crowding at the
// horizon), 128 azimuths over the full circle, independent of the class's quadrature.
std::array<double, kSpectralBins> direct_j(const FogLayer& fog, double z) {
  const SkyModel& sky = test_sky();
  const int nu = 600, nphi = 128;
  const double v_up = fog.column(z, 1.0, 0.0, fog.top_m() - z), v_down = fog.column(z, -1.0, 0.0, z - fog.bottom_m());
  std::array<double, kSpectralBins> sum{};
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere)
    for (int k = 0; k < nu; ++k) {
      const double u = (k + 0.5) / nu, wn = u * u, dw = 2 * u / nu, sz = std::sqrt(1 - wn * wn);
      const double w = hemisphere ? -wn : wn;
      const Spectrum t = fog.transmittance((hemisphere ? v_down : v_up) / wn);
      for (int j = 0; j < nphi; ++j) {
        const double phi = 2 * kPi * (j + 0.5) / nphi;
        const Radiance l = sky.sky_radiance_near_ground({sz * std::cos(phi), sz * std::sin(phi), w});
        for (int i = 0; i < kSpectralBins; ++i) sum[static_cast<size_t>(i)] += l[i] * t[i] * dw * 2 * kPi / nphi;
      }
    }
  return sum;
}

// ∫ τ ω0 (source) e^(−t) ds (source J/4π, or the multiple-scattering field's) by the trapezoidal rule in `steps` equal
// steps over the part of [s1, s2] in the layer, t in closed form from the viewpoint.
Spectrum fixed_step(const FogSkyLight& light, const Vec3& p, const Vec3& d, double s1, double s2, int steps) {
  const FogLayer& fog = light.layer();
  const RaySpan span = fog.clip(p.z, d.z, s1, s2);
  if (span.empty()) return Spectrum(0.0f);
  std::array<double, kSpectralBins> sum{};
  const double h = (span.hi - span.lo) / steps;
  for (int k = 0; k <= steps; ++k) {
    const double s = span.lo + k * h, weight = (k == 0 || k == steps) ? 0.5 * h : h;
    const double z = std::clamp(p.z + d.z * s, fog.bottom_m(), fog.top_m());
    const Spectrum j = light.source(z, -d.z, light.relative_azimuth(d));  // J/4π, or the multiple-scattering field's
    const Spectrum t = fog.transmittance(fog.column(p.z, d.z, 0.0, s));
    for (int i = 0; i < kSpectralBins; ++i)
      sum[static_cast<size_t>(i)] +=
          weight * fog.density(z) * fog.unit_density_extinction_bins()[static_cast<size_t>(i)] * j[i] * t[i];
  }
  Spectrum out;
  for (int i = 0; i < kSpectralBins; ++i)
    out[i] = static_cast<float>(fog.single_scattering_albedo() * sum[static_cast<size_t>(i)]);
  return out;
}

double worst_relative(const Spectrum& got, const Spectrum& want) {
  double worst = 0;
  for (int i = 0; i < kSpectralBins; ++i)
    worst = std::max(worst, double(std::abs(got[i] - want[i]) / std::abs(want[i])));
  return worst;
}

TEST(FogSkyLight, VanishingFogGivesTheSkysIntegral) {
  FogSettings s;
  s.density_at_ground = 1e-12;
  const FogLayer fog(s);
  const FogSkyLight light(fog, test_sky());
  const std::array<double, kSpectralBins> direct = direct_j(fog, 30.0);
  double worst = 0;
  for (double z : {-5.0, 0.0, 13.0, 30.0, 59.0, 60.0, 200.0})
    worst = std::max(worst, worst_relative(light.at(z), direct));
  worst = std::max(worst, worst_relative(light.unattenuated(), direct));
  std::cout << "[FogSkyLight] vanishing fog: J vs direct quadrature of the sky (600x2 x 128), worst bin " << worst
            << ", mean J " << bin_mean(light.unattenuated()) << " W m-2 nm-1\n";
  EXPECT_LT(worst, 0.01);
}

TEST(FogSkyLight, TableMatchesDirectQuadratureInDenseFog) {
  for (double h0 : {10.0, -15.0, std::numeric_limits<double>::infinity()}) {
    FogSettings s;
    s.scale_height_m = h0;
    s.density_at_ground = h0 < 0 ? 0.5 : 5.0;  // vertical optical depths of order 1–10
    const FogLayer fog(s);
    const FogSkyLight light(fog, test_sky());
    double worst = 0;
    for (double z : {0.0, 2.0, 10.0, 25.0, 45.0, 60.0})
      worst = std::max(worst, worst_relative(light.at(z), direct_j(fog, z)));
    std::cout << "[FogSkyLight] h0 = " << h0 << ": J table vs direct quadrature, worst bin " << worst << "\n";
    EXPECT_LT(worst, 0.02) << h0;
  }
}

TEST(FogSkyLight, LightDecreasesIntoDenseFog) {
  FogSettings s;
  s.density_at_ground = 5.0;  // 0.1 m⁻¹ at the ground, thinning upward (h0 = 10 m)
  const FogLayer fog(s);
  const FogSkyLight light(fog, test_sky());
  const double above = bin_mean(light.unattenuated());
  double previous = above;
  for (double z : {60.0, 40.0, 20.0, 10.0, 5.0}) {
    const double j = bin_mean(light.at(z));
    EXPECT_LT(j, previous) << z;
    previous = j;
  }
  // At the very bottom the ground below comes back into view through less and less fog
  // (the column downward vanishes at the bottom), so J rises again there, still below
  // the unattenuated value.
  const double j1 = bin_mean(light.at(1.0)), j0 = bin_mean(light.at(0.0));
  std::cout << "[FogSkyLight] dense fog (0.1 m-1 at the ground, h0 = 10 m): J/J_above at 60, 10, 5, 1, 0 m = "
            << bin_mean(light.at(60)) / above << ", " << bin_mean(light.at(10)) / above << ", " << previous / above
            << ", " << j1 / above << ", " << j0 / above << "\n";
  EXPECT_LT(previous, 0.5 * above);
  EXPECT_GT(j0, j1);
  EXPECT_LT(j0, above);
}

struct RayCase {
  const char* name;
  Vec3 p, d;
  double s1, s2;
};

TEST(FogSkyLight, AdaptivePitchMatchesFineFixedSteps) {
  // Both sources: the paper's J(z)/4π and the multiple-scattering field's, which
  // depends on the direction too.
  for (bool multiple : {false, true})
    for (double h0 : {10.0, -15.0}) {
      FogSettings s;
      s.multiple_scattering = multiple;
      s.scale_height_m = h0;
      s.density_at_ground = h0 > 0 ? 0.59 : 0.037;  // the paper's Figs. 8a and 8b
      const FogLayer fog(s);
      const FogSkyLight light(fog, test_sky());
      const RayCase cases[] = {
          {"horizontal z=1.6", {0, 0, 1.6}, {1, 0, 0}, 0, 4000},
          {"horizontal z=40", {0, 0, 40}, {0, 1, 0}, 0, 4000},
          {"up from z=1.6", {0, 0, 1.6}, {0, 0, 1}, 0, 1e4},
          {"slant up 5 deg", {0, 0, 1.6}, direction_from_altitude_azimuth(5, 30), 0, 1e4},
          {"down from z=55", {0, 0, 55}, {0, 0, -1}, 0, 1e4},
          {"down 10 deg from 100 m (across the top)", {0, 0, 100}, direction_from_altitude_azimuth(-10, 200), 0, 1e4},
          {"grazing 1 deg from 70 m (across the top)", {0, 0, 70}, direction_from_altitude_azimuth(-1, 0), 0, 1e5},
          {"segment 200-900 m, 2 deg", {0, 0, 3}, direction_from_altitude_azimuth(2, 90), 200, 900},
      };
      for (const RayCase& c : cases) {
        int steps = 0;
        const Spectrum got = light.in_scattered(c.p, c.d, c.s1, c.s2, &steps);
        const Spectrum want = fixed_step(light, c.p, c.d, c.s1, c.s2, 20000);
        const double error = worst_relative(got, want);
        std::cout << "[FogSkyLight] h0 = " << h0 << ", " << c.name << ": " << steps << " steps, I = " << bin_mean(want)
                  << " W m-2 sr-1 nm-1, worst bin error " << error << "\n";
        EXPECT_LT(error, 0.01) << c.name;
        EXPECT_LT(steps, 400) << c.name;
      }
    }
}

TEST(FogSkyLight, EndlessRaysStopByTheTailTest) {
  const FogLayer fog{FogSettings{}};
  const FogSkyLight light(fog, test_sky());
  int steps = 0;
  const double inf = std::numeric_limits<double>::infinity();
  const Spectrum endless = light.in_scattered({0, 0, 1.6}, {1, 0, 0}, 0, inf, &steps);
  const Spectrum long_ray = fixed_step(light, {0, 0, 1.6}, {1, 0, 0}, 0, 2e4, 20000);  // e^(−t) ≈ e^(−230) at the end
  std::cout << "[FogSkyLight] endless level ray: " << steps << " steps, error vs 20 km fixed step "
            << worst_relative(endless, long_ray) << "\n";
  EXPECT_LT(worst_relative(endless, long_ray), 0.01);
  EXPECT_GT(steps, 0);
}

TEST(FogSkyLight, VanishingDensityScattersNothing) {
  double previous = std::numeric_limits<double>::infinity();
  for (double rho0 : {0.59, 1e-3, 1e-6, 1e-9, 0.0}) {
    FogSettings s;
    s.density_at_ground = rho0;
    const FogLayer fog(s);
    const FogSkyLight light(fog, test_sky());
    const double i = bin_mean(light.in_scattered({0, 0, 1.6}, {1, 0, 0}, 0, 1000));
    EXPECT_LT(i, previous);
    if (rho0 > 0 && rho0 < 0.01) {  // thin fog: I ≈ τ·L/4π·J·length, linear in ρ0
      const double expected = rho0 * 0.02 * std::exp(-1.6 / 10.0) *
                              bin_mean(light.source(1.6, 0.0, light.relative_azimuth({1, 0, 0}))) * 1000;
      EXPECT_NEAR(i / expected, 1.0, 0.01) << rho0;
    }
    previous = i;
  }
  EXPECT_EQ(previous, 0.0);
}

TEST(FogSkyLight, NoNanForExtremeInputs) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double rho0 : {0.0, 1e-300, 0.59, 1e6, 1e250})
    for (double h0 : {1e-3, -1e-3, 10.0, -15.0, 1e300, inf}) {
      FogSettings s;
      s.density_at_ground = rho0;
      s.scale_height_m = h0;
      const FogLayer fog(s);
      const FogSkyLight light(fog, test_sky(), 8);
      for (double z : {-1e300, 0.0, 30.0, 60.0, 1e300})
        for (int i = 0; i < kSpectralBins; ++i) {
          ASSERT_TRUE(std::isfinite(light.at(z)[i]));
          ASSERT_GE(light.at(z)[i], 0.0f);
        }
      for (const Vec3& p : {Vec3{0, 0, -1e300}, Vec3{0, 0, 0}, Vec3{0, 0, 30}, Vec3{0, 0, 1e300}})
        for (const Vec3& d :
             {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{1, 0, 1e-300}, Vec3{1, 0, -1e-12}, Vec3{0, 0, 0}})
          for (double s2 : {0.0, 1e-9, 1e3, 1e300, inf}) {
            int steps = 0;
            const Spectrum r = light.in_scattered(p, d, 0.0, s2, &steps);
            for (int i = 0; i < kSpectralBins; ++i) {
              ASSERT_TRUE(std::isfinite(r[i])) << rho0 << " " << h0 << " " << p.z << " " << d.z << " " << s2;
              ASSERT_GE(r[i], 0.0f);
            }
            ASSERT_LE(steps, FogSkyLight::kMaxSteps);
          }
    }
}

}  // namespace
}  // namespace skylit
