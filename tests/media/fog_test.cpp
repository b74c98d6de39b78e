// Fog (§3.2, §5.1, Appendix): the layer's closed-form columns and the closed form of
// the in-scattered sunlight (Eqs. 17–28 for a bounded layer) against adaptive
// Gauss–Kronrod quadrature of their definitions, against hand-derived homogeneous
// cases and the paper's own formulas, continuity through the special cases, and
// finiteness for extreme inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include "../reference_quadrature.h"
#include "skylit/core/error.h"
#include "skylit/media/fog_layer.h"
#include "skylit/media/fog_phase.h"
#include "skylit/media/fog_settings.h"
#include "skylit/media/fog_sun_integral.h"

namespace skylit {
namespace {

using testing::integrate;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- The fog written straight from its definitions: Eqs. 2, 9, 10, 11, 12, 19, 21 ----

struct ReferenceFog {
  double rho0, h0, bottom, top, sigma;

  double density(double z) const { return (z < bottom || z > top) ? 0.0 : rho0 * std::exp(-z / h0); }

  // ∫ f over [lo, hi] cut where the ray z_p + z_v·s crosses the layer's faces.
  template <class F>
  double along_ray(const F& f, double z_p, double z_v, double lo, double hi, double rel_tol, bool grade = false) const {
    std::vector<double> cuts{lo};
    if (z_v != 0.0)
      for (double face : {bottom, top}) {
        const double s = (face - z_p) / z_v;
        if (s > lo && s < hi) cuts.push_back(s);
      }
    cuts.push_back(hi);
    std::sort(cuts.begin(), cuts.end());
    double sum = 0.0;
    for (size_t i = 0; i + 1 < cuts.size(); ++i)
      sum += grade ? graded(f, cuts[i], cuts[i + 1], rel_tol) : integrate(f, cuts[i], cuts[i + 1], rel_tol);
    return sum;
  }

  // Sunlight scattered from a piece of the layer is concentrated at one of its ends
  // (t + t' is monotonic along it), sometimes within a millimetre of a kilometre-long
  // piece, where 15 points see only zeros. So the piece is first cut into panels that
  // halve toward both ends, down to 2^−30 of its length (the grid's thinnest is ~1e-6).
  template <class F>
  static double graded(const F& f, double lo, double hi, double rel_tol) {
    const double half = 0.5 * (hi - lo);
    double sum = 0.0;
    for (int k = 0; k < 30; ++k) {
      const double outer = half * std::ldexp(1.0, -k), inner = 0.5 * outer;
      sum += integrate(f, lo + inner, lo + outer, rel_tol) + integrate(f, hi - outer, hi - inner, rel_tol);
    }
    const double last = half * std::ldexp(1.0, -30);
    return sum + integrate(f, lo, lo + last, rel_tol) + integrate(f, hi - last, hi, rel_tol);
  }

  double column(double z_p, double z_v, double s1, double s2) const {
    return along_ray([&](double s) { return density(z_p + z_v * s); }, z_p, z_v, s1, s2, 1e-13);
  }

  // Along the sun's path l from altitude z: z + z_L·l, from where it enters the layer to the top.
  double sun_column(double z, double z_sun) const {
    if (z >= top) return 0.0;
    const double l0 = z < bottom ? (bottom - z) / z_sun : 0.0, l1 = (top - z) / z_sun;
    return integrate([&](double l) { return density(z + z_sun * l); }, l0, l1, 1e-13);
  }

  // Eq. 21: ∫ τ(s)·e^(−t'(s))·e^(−t(s)) ds with t, t' by quadrature too.
  double sun_weight(double z_p, double z_v, double z_sun, double s1, double s2) const {
    const auto integrand = [&](double s) {
      const double z = z_p + z_v * s, rho = density(z);
      if (rho == 0.0) return 0.0;
      const double t = sigma * column(z_p, z_v, 0.0, s), t_sun = sigma * sun_column(z, z_sun);
      return sigma * rho * std::exp(-t - t_sun);
    };
    return along_ray(integrand, z_p, z_v, s1, s2, 1e-11, true);
  }
};

FogSettings settings_for(const ReferenceFog& r) {
  FogSettings s;
  s.density_at_ground = r.rho0;
  s.scale_height_m = r.h0;
  s.bottom_altitude_m = r.bottom;
  s.top_altitude_m = r.top;
  s.unit_density_extinction_per_m = r.sigma;
  return s;
}

double relative_error(double got, double want) {
  if (want == 0.0) return got == 0.0 ? 0.0 : kInf;
  return std::abs(got / want - 1.0);
}

// Results below this are "nothing" for both (e^(−700)); compared absolutely.
constexpr double kNegligible = 1e-300;

bool close(double got, double want, double rel) { return std::abs(got - want) <= rel * std::abs(want) + kNegligible; }

const std::vector<double> kScaleHeights = {10.0, 50.0, -15.0, -40.0};
const std::vector<double> kDensities = {0.037, 0.59};
const std::vector<double> kViewCosines = {0.0, 1e-9, -1e-9, 1e-4, -1e-4, 0.1, -0.3, 0.9};
const std::vector<double> kSunCosines = {1e-3, 0.05, 0.5, 1.0};  // 0.06°, 2.9°, 30°, 90°
// A layer on the ground and one lifted off it; viewpoints below, in and above them.
const std::vector<std::pair<double, double>> kLayers = {{0.0, 60.0}, {10.0, 80.0}};
const std::vector<double> kViewpoints = {2.0, 30.0, 120.0};
const std::vector<std::pair<double, double>> kSegments = {{0.0, 40.0}, {5.0, 300.0}, {50.0, 5000.0}};

// ---------------------------------------------------------------- the layer ----

TEST(FogLayer, DensityIsEq2InsideTheLayerAndZeroOutside) {
  FogSettings s;
  s.density_at_ground = 0.037;
  s.scale_height_m = -15.0;
  s.bottom_altitude_m = 5.0;
  s.top_altitude_m = 60.0;
  const FogLayer layer(s);
  EXPECT_EQ(layer.density(4.999), 0.0);
  EXPECT_EQ(layer.density(60.001), 0.0);
  for (double z : {5.0, 20.0, 45.0, 60.0})
    EXPECT_NEAR(layer.density(z), 0.037 * std::exp(z / 15.0), 1e-15 * layer.density(z));
  s.scale_height_m = kInf;  // homogeneous
  EXPECT_DOUBLE_EQ(FogLayer(s).density(30.0), 0.037);
}

TEST(FogLayer, ExtinctionFollowsEq9) {
  FogSettings s;
  s.unit_density_extinction_per_m = 0.02;
  s.reference_wavelength_nm = 550.0;
  s.wavelength_exponent = 1.3;
  const FogLayer layer(s);
  EXPECT_DOUBLE_EQ(layer.unit_density_extinction_per_m(550.0), 0.02);
  EXPECT_NEAR(layer.unit_density_extinction_per_m(440.0), 0.02 * std::pow(0.8, -1.3), 1e-16);
  for (int i = 0; i < kSpectralBins; ++i)
    EXPECT_DOUBLE_EQ(layer.unit_density_extinction_bins()[static_cast<size_t>(i)],
                     layer.unit_density_extinction_per_m(kGrid.center_nm(i)));
  // The default b = 0: the same extinction in every bin (white fog).
  const FogLayer white{FogSettings{}};
  for (double sigma : white.unit_density_extinction_bins()) EXPECT_EQ(sigma, 0.02);
}

TEST(FogLayer, TransmittanceIsBeerLambertPerBin) {
  // Coloured fog (b = 1.3) bin by bin, and grey fog (b = 0), which takes one exponential
  // for all bins, from clear to opaque.
  for (double b : {1.3, 0.0}) {
    FogSettings s;
    s.wavelength_exponent = b;
    const FogLayer layer(s);
    ASSERT_EQ(layer.is_grey(), b == 0.0);
    for (double column : {0.0, 25.0, 300.0, 4000.0}) {
      const Spectrum t = layer.transmittance(column);
      for (int i = 0; i < kSpectralBins; ++i)
        EXPECT_NEAR(t[i], std::exp(-layer.unit_density_extinction_bins()[static_cast<size_t>(i)] * column), 1e-7)
            << "b " << b << " column " << column << " bin " << i;
    }
    const Spectrum opaque = layer.transmittance(kOpaqueColumnM);
    for (int i = 0; i < kSpectralBins; ++i) EXPECT_EQ(opaque[i], 0.0f) << "b " << b;
  }
}

TEST(FogLayer, ColumnMatchesQuadrature) {
  // Eq. 10 in closed form along view rays, clipped to the layer, against quadrature of
  // the density, including level and nearly level rays and the homogeneous limit.
  double worst = 0;
  for (double h0 : {10.0, 50.0, -15.0, -40.0, 1e12, -1e12, kInf})
    for (const auto& [bottom, top] : kLayers) {
      const ReferenceFog ref{0.59, h0, bottom, top, 1.0};
      const FogLayer layer(settings_for(ref));
      for (double z_p : {-20.0, 2.0, 30.0, 120.0})
        for (double z_v : {0.0, 1e-9, -1e-9, 1e-4, -1e-4, 0.1, -0.3, 0.9, 1.0, -1.0})
          for (const auto& [s1, s2] : kSegments) {
            const double got = layer.column(z_p, z_v, s1, s2), want = ref.column(z_p, z_v, s1, s2);
            worst = std::max(worst, want > 0 ? relative_error(got, want) : 0.0);
            EXPECT_TRUE(close(got, want, 1e-10)) << "h0 " << h0 << " z_p " << z_p << " z_v " << z_v << " [" << s1
                                                 << ", " << s2 << "]: " << got << " vs " << want;
          }
    }
  std::printf("[fog] view-ray column vs quadrature: worst relative error %.2e\n", worst);
}

TEST(FogLayer, ColumnBetweenPointsIsTheRayColumn) {
  const FogLayer layer{FogSettings{}};
  const Vec3 a{3, -4, 2}, b{103, 46, 40};
  const double d = length(b - a);
  EXPECT_NEAR(layer.column_between(a, b), layer.column(a.z, (b.z - a.z) / d, 0.0, d), 1e-14);
  EXPECT_NEAR(layer.column_between(b, a), layer.column_between(a, b), 1e-13);
  EXPECT_EQ(layer.column_between(a, a), 0.0);
}

TEST(FogLayer, SunColumnMatchesQuadratureAndIsFiniteWhenDenserUpward) {
  // Eq. 19 with the layer's top: finite for h0 < 0, and for points below the layer the
  // whole layer's column.
  double worst = 0;
  for (double h0 : {10.0, 50.0, -15.0, -40.0, kInf})
    for (const auto& [bottom, top] : kLayers) {
      const ReferenceFog ref{0.59, h0, bottom, top, 1.0};
      const FogLayer layer(settings_for(ref));
      for (double z : {-5.0, 0.0, 10.0, 30.0, top - 0.1, top, 100.0})
        for (double z_sun : kSunCosines) {
          const double got = layer.sun_column(z, z_sun), want = ref.sun_column(z, z_sun);
          EXPECT_TRUE(std::isfinite(got));
          worst = std::max(worst, want > 0 ? relative_error(got, want) : 0.0);
          EXPECT_TRUE(close(got, want, 1e-10))
              << "h0 " << h0 << " z " << z << " z_L " << z_sun << ": " << got << " vs " << want;
        }
    }
  std::printf("[fog] sun column vs quadrature: worst relative error %.2e\n", worst);
}

TEST(FogLayer, SunColumnIsEq19WhenTheTopIsFarAbove) {
  // The paper's unbounded layer (h0 > 0): t' = ρ0·h0/z_L·e^(−z/h0) per unit extinction.
  FogSettings s;
  s.density_at_ground = 0.59;
  s.scale_height_m = 10.0;
  s.top_altitude_m = 1000.0;  // e^(−100): gone
  const FogLayer layer(s);
  for (double z : {0.0, 7.0, 30.0})
    for (double z_sun : {0.05, 0.5, 1.0})
      EXPECT_NEAR(layer.sun_column(z, z_sun), 0.59 * 10.0 / z_sun * std::exp(-z / 10.0),
                  1e-13 * layer.sun_column(z, z_sun));
}

TEST(FogLayer, NoSunlightFromBelowTheHorizon) {
  const FogLayer layer{FogSettings{}};
  for (double z_sun : {0.0, -1e-12, -0.5, -1.0}) EXPECT_EQ(layer.sun_column(10.0, z_sun), kOpaqueColumnM);
  EXPECT_TRUE(std::isfinite(layer.sun_column(10.0, 1e-300)));
  EXPECT_EQ(layer.sun_column(100.0, 0.3), 0.0);  // above the layer
}

TEST(FogLayer, VisibilityAndDensityRoundTrip) {
  // Koschmieder at 550 nm: σ(550)·ρ0 = 3.912/V.
  for (double b : {0.0, 1.3})
    for (double lambda0 : {550.0, 500.0}) {
      FogSettings s;
      s.wavelength_exponent = b;
      s.reference_wavelength_nm = lambda0;
      for (double v : {20.0, 200.0, 1000.0, 10000.0}) {
        const double rho = fog_density_from_visibility(v, s);
        EXPECT_NEAR(fog_visibility_from_density(rho, s), v, 1e-12 * v);
        s.ground_visibility_m = v;
        const FogLayer layer(s);
        EXPECT_NEAR(layer.density_at_ground(), rho, 1e-15 * rho);
        // Over V at the ground through a homogeneous layer, 2 % gets through at 550 nm.
        s.scale_height_m = kInf;
        const FogLayer uniform(s);
        const double t = uniform.unit_density_extinction_per_m(550.0) * uniform.column(0.0, 0.0, 0.0, v);
        EXPECT_NEAR(std::exp(-t), 0.02, 1e-4);
        s.scale_height_m = 10.0;
        s.ground_visibility_m.reset();
      }
    }
  // The defaults make the paper's densities what its Fig. 8 shows (docs/fog.md):
  // ρ0 = 0.59 a moderate fog, ρ0 = 0.037 a light haze at the ground.
  const FogSettings defaults;
  EXPECT_NEAR(fog_visibility_from_density(0.59, defaults), 331.5, 0.1);
  EXPECT_NEAR(fog_visibility_from_density(0.037, defaults), 5286.5, 0.1);
}

TEST(FogLayer, RejectsBadSettings) {
  const auto bad = [](auto change) {
    FogSettings s;
    change(s);
    EXPECT_THROW(FogLayer{s}, InputError);
  };
  bad([](FogSettings& s) { s.scale_height_m = 0.0; });
  bad([](FogSettings& s) { s.top_altitude_m = s.bottom_altitude_m; });
  bad([](FogSettings& s) { s.density_at_ground = -1.0; });
  bad([](FogSettings& s) { s.ground_visibility_m = 0.0; });
  bad([](FogSettings& s) { s.unit_density_extinction_per_m = -0.1; });
  bad([](FogSettings& s) { s.reference_wavelength_nm = 0.0; });
  bad([](FogSettings& s) { s.single_scattering_albedo = 1.5; });
  bad([](FogSettings& s) { s.droplet_diameter_um = 2.0; });
  bad([](FogSettings& s) {
    s.phase = FogPhase::henyey_greenstein;
    s.asymmetry = 1.0;
  });
}

// ----------------------------------------------------------- phase function ----

TEST(FogPhase, NormalisedWithTheDocumentedMeanCosine) {
  for (double d : {5.0, 15.0, 50.0}) {
    const DropletPhaseParameters p = DropletPhaseParameters::for_diameter(d);
    const auto over_sphere = [&](auto f) { return 2.0 * kPi * integrate(f, -1.0, 1.0, 1e-12); };
    const double norm = over_sphere([&](double mu) { return droplet_phase(mu, p); });
    const double mean_cos = over_sphere([&](double mu) { return mu * droplet_phase(mu, p); });
    EXPECT_NEAR(norm, 1.0, 1e-9) << d;
    EXPECT_NEAR(mean_cos, droplet_phase_mean_cosine(p), 1e-9) << d;
    std::printf("[fog] droplet phase d = %g µm: g_HG %.4f, g_D %.4f, α %.2f, w_D %.4f, mean cosine %.4f\n", d, p.g_hg,
                p.g_draine, p.alpha, p.draine_weight, mean_cos);
  }
  FogSettings s;
  s.phase = FogPhase::henyey_greenstein;
  s.asymmetry = 0.85;
  const FogLayer layer(s);
  EXPECT_NEAR(2.0 * kPi * integrate([&](double mu) { return layer.phase(mu); }, -1.0, 1.0, 1e-12), 1.0, 1e-9);
}

// ------------------------------------------------------ in-scattered sunlight ----

TEST(FogSunIntegral, ClosedFormMatchesQuadratureOverTheGrid) {
  // h0 of both signs, both of the paper's densities, level, nearly level, rising and
  // falling view rays, the sun from the horizon to the zenith, viewpoints below, in and
  // above the layer, segments inside it and crossing its faces. σ = 0.02 m⁻¹ (default τ0).
  double worst = 0, worst_value = 0;
  int compared = 0, nonzero = 0;
  for (double h0 : kScaleHeights)
    for (double rho0 : kDensities)
      for (const auto& [bottom, top] : kLayers) {
        const ReferenceFog ref{rho0, h0, bottom, top, 0.02};
        const FogLayer layer(settings_for(ref));
        for (double z_p : kViewpoints)
          for (double z_v : kViewCosines)
            for (double z_sun : kSunCosines)
              for (const auto& [s1, s2] : kSegments) {
                const double got = fog_sun_weight(layer, z_p, z_v, z_sun, s1, s2, 550.0);
                const double want = ref.sun_weight(z_p, z_v, z_sun, s1, s2);
                ++compared;
                if (want > kNegligible) {
                  ++nonzero;
                  if (relative_error(got, want) > worst) {
                    worst = relative_error(got, want);
                    worst_value = want;
                  }
                }
                EXPECT_TRUE(close(got, want, 1e-4))
                    << "h0 " << h0 << " ρ0 " << rho0 << " layer [" << bottom << ", " << top << "] z_p " << z_p
                    << " z_v " << z_v << " z_L " << z_sun << " [" << s1 << ", " << s2 << "]: " << got << " vs " << want;
              }
      }
  std::printf(
      "[fog] sun in-scatter vs quadrature: %d cases (%d non-zero), worst relative error %.2e (at a value %.1e)\n",
      compared, nonzero, worst, worst_value);
  EXPECT_LT(worst, 1e-8);
}

TEST(FogSunIntegral, ViewParallelToTheSunMatchesQuadrature) {
  // z_v → z_L, the paper's Eq. 25 and the limit where Eq. 28's denominator vanishes.
  double worst = 0;
  for (double h0 : kScaleHeights)
    for (double rho0 : kDensities) {
      const ReferenceFog ref{rho0, h0, 0.0, 60.0, 0.02};
      const FogLayer layer(settings_for(ref));
      for (double z_sun : {0.05, 0.5, 1.0})
        for (double delta : {0.0, 1e-9, -1e-9, 1e-5, -1e-5})
          for (double z_p : {2.0, 30.0})
            for (const auto& [s1, s2] : kSegments) {
              const double z_v = std::min(1.0, z_sun - delta);
              const double got = fog_sun_weight(layer, z_p, z_v, z_sun, s1, s2, 550.0);
              const double want = ref.sun_weight(z_p, z_v, z_sun, s1, s2);
              if (want > kNegligible) worst = std::max(worst, relative_error(got, want));
              EXPECT_TRUE(close(got, want, 1e-4))
                  << "h0 " << h0 << " z_L " << z_sun << " δ " << delta << " z_p " << z_p;
            }
    }
  std::printf("[fog] sun in-scatter, view ∥ sun, vs quadrature: worst relative error %.2e\n", worst);
  EXPECT_LT(worst, 1e-8);
}

TEST(FogSunIntegral, ContinuousThroughTheSpecialCases) {
  // Where the paper switches formulas (z_v = 0, z_v = z_L) and at the homogeneous limit
  // (1/h0 = 0) the closed form must not jump. The values at δ, 2δ, 3δ to one side,
  // extrapolated quadratically to 0, 3w(δ) − 3w(2δ) + w(3δ) = w(0⁺) + O(δ³), cancel the
  // slope and the curvature (which matter where w ∝ e^(−180) is steep); what is left of
  // the difference from w(0) is the jump, plus rounding. Rounding of w = e^(−X)·… is
  // about X·1e-16 relative, so the bound is 1e-12 + 2e-14·|ln w| (measured at ordinary,
  // not special, points the same J reaches 2e-12 for w ~ 1e-81).
  double worst = 0, worst_ordinary = 0;
  const auto check = [&](auto w, const char* what) {
    for (double delta : {1e-9, -1e-9}) {
      const double w0 = w(0.0), jump = std::abs((3.0 * w(delta) - 3.0 * w(2.0 * delta) + w(3.0 * delta) - w0) / w0);
      worst = std::max(worst, jump);
      if (w0 > 1e-20) worst_ordinary = std::max(worst_ordinary, jump);
      EXPECT_LT(jump, 1e-12 + 2e-14 * std::abs(std::log(w0))) << what << ", δ " << delta << ", w " << w0;
    }
  };
  for (double h0 : kScaleHeights)
    for (const auto& segment : kSegments) {
      // Plain variables, not structured bindings: the lambdas below capture them, which
      // C++20 allows for bindings but Clang before 16 does not implement.
      const double s1 = segment.first, s2 = segment.second;
      const FogLayer layer(settings_for({0.59, h0, 0.0, 60.0, 0.02}));
      for (double z_sun : {0.05, 0.5, 1.0}) {
        check([&](double d) { return fog_sun_weight(layer, 30.0, d, z_sun, s1, s2, 550.0); }, "z_v → 0");
        check([&](double d) { return fog_sun_weight(layer, 2.0, z_sun - d, z_sun, s1, s2, 550.0); }, "z_v → z_L");
      }
    }
  for (double z_v : {0.0, 0.1, -0.3, 0.5})
    for (double z_sun : {0.05, 0.5})
      check(
          [&](double eta) {
            return fog_sun_weight(FogLayer(settings_for({0.59, 1.0 / eta, 0.0, 60.0, 0.02})), 30.0, z_v, z_sun, 0.0,
                                  300.0, 550.0);
          },
          "1/h0 → 0");
  std::printf("[fog] largest jump across a special case: %.2e relative (%.2e where w > 1e-20)\n", worst,
              worst_ordinary);
}

TEST(FogSunIntegral, HomogeneousLayerMatchesHandDerivedClosedForms) {
  // h0 = ±∞ (and 1e15 as its limit): τ = σρ0 = k throughout a layer [0, H].
  const double rho0 = 0.59, sigma = 0.02, k = rho0 * sigma, height = 60.0;
  for (double h0 : {kInf, -kInf, 1e15}) {
    const FogLayer layer(settings_for({rho0, h0, 0.0, height, sigma}));
    const auto w = [&](double z_p, double z_v, double z_sun, double s1, double s2) {
      return fog_sun_weight(layer, z_p, z_v, z_sun, s1, s2, 550.0);
    };
    for (double z_sun : {0.05, 0.5, 1.0}) {
      // A level ray at z: t' = k(H − z)/z_L everywhere, ∫ k e^(−k s) ds over [s1, s2].
      const double z = 20.0, sun = std::exp(-k * (height - z) / z_sun);
      EXPECT_NEAR(w(z, 0.0, z_sun, 0.0, 1e6), sun, 1e-12 * sun);  // the infinite ray: E·F·e^(−t')
      EXPECT_NEAR(w(z, 0.0, z_sun, 10.0, 90.0), sun * (std::exp(-k * 10.0) - std::exp(-k * 90.0)), 1e-12 * sun);
    }
    // Looking straight down from the top with the sun overhead: ∫₀ᴴ k e^(−2kd) dd.
    EXPECT_NEAR(w(height, -1.0, 1.0, 0.0, height), 0.5 * (1.0 - std::exp(-2.0 * k * height)), 1e-12);
    // ... and from far above, through the whole layer: the same.
    EXPECT_NEAR(w(500.0, -1.0, 1.0, 0.0, 1000.0), 0.5 * (1.0 - std::exp(-2.0 * k * height)), 1e-12);
    // Looking straight up at an overhead sun: t + t' is constant, k(H − z), over a path
    // of length H − z.
    EXPECT_NEAR(w(15.0, 1.0, 1.0, 0.0, 100.0), k * 45.0 * std::exp(-k * 45.0), 1e-12);
  }
}

TEST(FogSunIntegral, ReproducesTheAppendixForAnUnboundedLayer) {
  // The paper's Eqs. 22–28 (its layer is unbounded above, h0 > 0): a top 40 scale
  // heights up is the same to e^(−40). Eq. 28 as printed has the opposite sign — its
  // bracket runs from u(s1) to u(s2) where Eqs. 23 and 25 run from s2 to s1 — so the
  // test checks that the printed form is the negative of the integral.
  const double rho0 = 0.59, sigma = 0.02, h0 = 10.0, z_p = 20.0;
  const FogLayer layer(settings_for({rho0, h0, -1000.0, z_p + 40.0 * h0, sigma}));
  const double alpha = rho0 * sigma * std::exp(-z_p / h0);  // Eq. 22
  for (double z_sun : {0.05, 0.5, 1.0})
    for (const auto& [s1, s2] : std::vector<std::pair<double, double>>{{0.0, 50.0}, {10.0, 150.0}}) {
      // Eq. 23: z_v = 0.
      const double eq23 = std::exp(-alpha * h0 / z_sun) * (std::exp(-alpha * s1) - std::exp(-alpha * s2));
      EXPECT_NEAR(fog_sun_weight(layer, z_p, 0.0, z_sun, s1, s2, 550.0), eq23, 1e-12 * eq23);
      // Eq. 25: z_v = z_L.
      const double z_v = z_sun;
      const double eq25 =
          alpha * std::exp(-alpha * h0 / z_v) * h0 / z_v * (std::exp(-z_v * s1 / h0) - std::exp(-z_v * s2 / h0));
      EXPECT_NEAR(fog_sun_weight(layer, z_p, z_v, z_sun, s1, s2, 550.0), eq25, 1e-12 * eq25);
      // Eq. 28: the general case, with u = e^(−z_v s/h0) (Eq. 26).
      for (double zv : {0.1, -0.1, 0.7}) {
        if (zv == z_sun) continue;
        const double c = alpha * h0 * (1.0 / zv - 1.0 / z_sun);
        const double u1 = std::exp(-zv * s1 / h0), u2 = std::exp(-zv * s2 / h0);
        const double printed = std::exp(-alpha * h0 / zv) / (1.0 - zv / z_sun) * (std::exp(c * u2) - std::exp(c * u1));
        const double got = fog_sun_weight(layer, z_p, zv, z_sun, s1, s2, 550.0);
        EXPECT_GT(got, 0.0);
        EXPECT_NEAR(got, -printed, 1e-10 * got) << "z_v " << zv << " z_L " << z_sun;
      }
    }
}

TEST(FogSunIntegral, NothingWithoutSunOrFog) {
  const FogLayer layer{FogSettings{}};
  for (double z_sun : {0.0, -1e-300, -0.2, -1.0})
    EXPECT_EQ(fog_sun_weight(layer, 10.0, 0.1, z_sun, 0.0, 500.0, 550.0), 0.0);
  EXPECT_EQ(fog_sun_weight(layer, 120.0, 0.0, 0.5, 0.0, 500.0, 550.0), 0.0);  // level ray above the layer
  EXPECT_EQ(fog_sun_weight(layer, 120.0, 0.2, 0.5, 0.0, 500.0, 550.0), 0.0);  // rising away from it
  EXPECT_EQ(fog_sun_weight(layer, 10.0, 0.1, 0.5, 30.0, 30.0, 550.0), 0.0);   // empty segment
  // A grazing sun: no NaN; only the top of the layer, where the sun's path through fog
  // is short, still sends a (vanishing) share: about z_L/z_v of e^(−T).
  const double grazing = fog_sun_weight(layer, 10.0, 0.1, 1e-300, 0.0, 500.0, 550.0);
  EXPECT_GE(grazing, 0.0);
  EXPECT_LT(grazing, 1e-298);
  EXPECT_EQ(fog_sun_weight(layer, 10.0, 0.0, 1e-300, 0.0, 500.0, 550.0), 0.0);  // level: all of it deep in fog
  FogSettings clear;
  clear.density_at_ground = 0.0;
  EXPECT_EQ(fog_sun_weight(FogLayer(clear), 10.0, 0.1, 0.5, 0.0, 500.0, 550.0), 0.0);
}

TEST(FogSunIntegral, FiniteForExtremeInputs) {
  // A sweep over absurd but finite values: weights finite and in [0, 1], columns finite
  // and ≥ 0.
  const std::vector<double> densities = {0.0, 1e-300, 1e-3, 1.0, 1e5, 1e300};
  const std::vector<double> heights = {1e-300, -1e-300, 1e-6, -1e-6, 1.0, -1.0, 1e6, -1e6, 1e300, -1e300, kInf, -kInf};
  const std::vector<std::pair<double, double>> layers = {{0.0, 60.0}, {-1e300, 1e300}, {-1e-300, 1e-300}};
  const std::vector<double> points = {-1e300, -50.0, 0.0, 30.0, 1e300};
  const std::vector<double> cosines = {-1.0, -1e-300, 0.0, 1e-300, 1e-9, 0.5, 1.0};
  const std::vector<std::pair<double, double>> segments = {{0.0, 0.0}, {0.0, 1e-300}, {0.0, 100.0}, {1e3, 1e300}};
  const std::vector<double> sigmas = {0.0, 1e-300, 1.0, 1e300};
  long checked = 0, bad = 0;
  for (double rho0 : densities)
    for (double h0 : heights)
      for (const auto& [bottom, top] : layers) {
        const FogLayer layer(settings_for({rho0, h0, bottom, top, 1.0}));
        for (double z_p : points) {
          if (!std::isfinite(layer.density(z_p)) || layer.density(z_p) < 0) ++bad;
          for (double z_v : cosines) {
            for (const auto& [s1, s2] : segments) {
              const double n = layer.column(z_p, z_v, s1, s2);
              if (!std::isfinite(n) || n < 0) ++bad;
              for (double z_sun : cosines) {
                const FogSunSegment segment = fog_sun_segment(layer, z_p, z_v, z_sun, s1, s2);
                for (double sigma : sigmas) {
                  const double w = fog_sun_weight(segment, sigma);
                  ++checked;
                  if (!std::isfinite(w) || w < 0.0 || w > 1.0 + 1e-12) {
                    if (++bad < 10)
                      ADD_FAILURE() << "weight " << w << " for ρ0 " << rho0 << " h0 " << h0 << " layer [" << bottom
                                    << ", " << top << "] z_p " << z_p << " z_v " << z_v << " z_L " << z_sun << " ["
                                    << s1 << ", " << s2 << "] σ " << sigma;
                  }
                }
              }
            }
            const double n_sun = layer.sun_column(z_p, z_v);
            if (!std::isfinite(n_sun) || n_sun < 0) ++bad;
          }
        }
      }
  EXPECT_EQ(bad, 0) << "of " << checked;
}

TEST(FogSunIntegral, SpectrumIsAlbedoPhaseIrradianceAndWeightPerBin) {
  FogSettings s;
  s.wavelength_exponent = 1.3;  // so that the bins differ
  s.single_scattering_albedo = 0.9;
  const FogLayer layer(s);
  const Vec3 eye{0, 0, 1.7}, view = normalize(Vec3{1, 0.2, 0.05}), sun = direction_from_altitude_azimuth(20.0, 100.0);
  Spectrum irradiance;
  for (int i = 0; i < kSpectralBins; ++i) irradiance[i] = static_cast<float>(1.0 + 0.01 * i);
  const Spectrum got = fog_sun_inscatter(layer, eye, view, sun, 3.0, 400.0, irradiance);
  const double phase = layer.phase(dot(view, sun));
  for (int i = 0; i < kSpectralBins; ++i) {
    const double want =
        0.9 * phase * irradiance[i] * fog_sun_weight(layer, eye.z, view.z, sun.z, 3.0, 400.0, kGrid.center_nm(i));
    EXPECT_NEAR(got[i], want, 1e-6 * want) << i;
  }
  EXPECT_GT(got[0], 0.0f);
  // The default white fog: the same weight in every bin, so the spectrum is E's shape.
  const FogLayer white{FogSettings{}};
  const Spectrum flat = fog_sun_inscatter(white, eye, view, sun, 3.0, 400.0, Spectrum(2.0f));
  const double w = fog_sun_weight(white, eye.z, view.z, sun.z, 3.0, 400.0, 550.0);
  for (int i = 0; i < kSpectralBins; ++i) EXPECT_NEAR(flat[i], 2.0 * white.phase(dot(view, sun)) * w, 1e-6 * flat[i]);
}

}  // namespace
}  // namespace skylit
