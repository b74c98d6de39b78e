// Multiple scattering against an independent Monte Carlo reference: a small spectral
// path tracer in the spherical shell that shares only the medium's coefficients, the
// phase functions and the (separately validated) transmittance table with the model.
//
// Backward paths start at the observer on the ground; free flights by delta tracking
// against one majorant (Rayleigh and aerosol extinction at the ground plus ozone at
// its peak); at every real collision the throughput takes the single-scattering albedo
// σ_s/σ_t and next-event estimation adds the sun through TransmittanceTable::sun (bent
// by refraction, as the model's sun is; the scattered light's paths stay straight)
// with the mixed phase function (σ_R P_R + σ_A P_A)/σ_s; new directions come from a
// 50/50 mixture of Henyey–Greenstein(g) and isotropic, weighted by phase/pdf; the
// ground is Lambertian with the model's albedo; Russian roulette ends long paths. All
// per unit extraterrestrial irradiance, like ScatteringIntegrator::along_ray. Each
// path carries two throughputs: the physical one, and one in which every scattering
// after the first is isotropic, which is the assumption Hillaire (2020) builds his
// multiple-scattering approximation on; so the same paths measure both the physics and
// the approximation's implementation.
//
// Measured (bins 5.13 nm wide at 450 and 650 nm, 51,200 paths per view, suns at 60, 30,
// 10 and 4°; the model is the full model's along_ray with 400 segments; totals compare
// the model with its own single scattering plus the path tracer's orders ≥ 2, which
// removes the first order's Monte Carlo noise — the first order is checked on its own):
//   * order 1 against the integrator's single scattering: −3.4 … +1.2 %, at most 1.9
//     standard errors (with 1 M paths per view in a prototype: within 0.2 %);
//   * the orders fall geometrically: order k+1 / order k is 0.07–0.53 for k ≥ 2; orders
//     ≥ 6 carry up to 0.4 % of the total at 650 nm and up to 2.3 % at 450 nm;
//   * with isotropic higher orders (Hillaire's assumption) the model's total is low by
//     0.4–6 % (its orders ≥ 2 by 5–14 %): f_ms leaves out the ground's reflection of
//     multiply scattered light (about 4 of those %, measured by setting the albedo to
//     0), and the table's quadrature (64 directions × 20 equal steps) under-resolves
//     the 1.2 km aerosol layer near the ground (Ψ_ms off by −9 … +20 % there against
//     1,024 directions × 200 steps);
//   * with the physical, forward-peaked aerosol phase function the higher orders are far
//     from isotropic — a multiply scattered aureole round the sun, less light opposite
//     it, more of it carried down to the ground at low sun — which the approximation
//     cannot represent: its total is off by −21 % … +28 % depending on direction, its
//     orders ≥ 2 by −49 % … +82 % (650 nm, 45° opposite the sun at 60°: +28 %; 450 nm,
//     10° up opposite a sun at 4–10°: −21 %); the irradiance on the horizontal plane
//     by +3.5/+7.1 % at sun 60°, −2.5/+2.3 % at 30° and −6 … −11 % at 4–10° (450/650 nm;
//     remeasured after e165070, the other numbers here are from before it);
//   * with the sun 4° below the horizon the model's sky was 4–78 % too bright (its orders
//     ≥ 2 by 17–127 %), as much against the path tracer's isotropic higher orders: not
//     the phase function but Ψ_ms's table, linear in μ_s with 20 rows across the
//     terminator, where Ψ_ms changes by orders of magnitude. With log Ψ_ms in 40 rows
//     (issue 15) the model is within −19 … +5 % of the isotropic paths (each within
//     2.3σ) and −20 … +7 % of the physical ones (after issue 15's aerosol, remeasured).
#include <gtest/gtest.h>

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "monte_carlo_paths.h"
#include "sky_reference.h"
#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/phase_functions.h"
#include "skylit/atmosphere/shell_geometry.h"
#include "sunlit_line_sky.h"

namespace skylit {
namespace {

using test_reference::around;
using test_reference::direction_from_sun_frame;
using test_reference::Estimate;
using test_reference::estimate_from_chunks;
using test_reference::kViews;
using test_reference::Random;
using test_reference::sample_henyey_greenstein;
using test_reference::View;

// Two bins, at 450 nm (Rayleigh and aerosols both matter; most multiple scattering)
// and 650 nm (aerosols dominate; least), in one atmosphere of 40 bins 5.13 nm wide.
constexpr int kBlue = 0, kRed = kSpectralBins - 1;
SpectralBands monte_carlo_bands() { return SpectralBands::consecutive(450.0, 200.0 / (kSpectralBins - 1)); }

constexpr int kMaxOrder = 30;  // orders above 30 carry less than 0.5^30 of the light
constexpr int kChunks = 64;    // fixed: the result does not depend on the thread count

// The first four are above the horizon; kTwilight is −4°.
constexpr std::array<double, 7> kSunElevationsDeg{60, 30, 10, 4, 0, -4, -8};
constexpr int kTwilight = 5;
constexpr int kSuns = static_cast<int>(kSunElevationsDeg.size());

// Per sun: each order, orders ≥ 2 and all orders, physical and with isotropic higher orders.
struct ViewResult {
  std::array<std::array<Estimate, kMaxOrder + 1>, kSuns> order;
  std::array<Estimate, kSuns> multiple, total;
  std::array<Estimate, kSuns> multiple_isotropic, total_isotropic;
  std::array<Estimate, kSuns> tail;  // orders ≥ 6
  std::array<double, kSuns> model_single{}, model_full{}, model_hillaire{};
};

class MonteCarloSky {
 public:
  // Each chunk traces its own 25 × 32 strata of the starting direction once (used by the
  // horizontal plane, whose first direction is random): an unbiased, stratified
  // estimate per chunk; standard errors come from the spread of the 64 chunk means.
  static constexpr int kStrataCosine = 25, kStrataAzimuth = 32;
  static constexpr int kPathsPerChunk = kStrataCosine * kStrataAzimuth;
  static_assert(kChunks * kPathsPerChunk == 51'200, "the paths the docs quote");

  // Tally slots per sun: orders 1..kMaxOrder, then orders ≥ 2, all orders, both again
  // with isotropic scattering after the first event, and orders ≥ 6.
  static constexpr size_t kSlots = kMaxOrder + 6;

  explicit MonteCarloSky(const Atmosphere& atmosphere)
      : atmosphere_(atmosphere), aerosol_phase_(atmosphere.settings().aerosol) {}

  ViewResult run(int bin, int view_index) const {
    const View& view = kViews[static_cast<size_t>(view_index)];
    std::vector<std::vector<double>> chunk_sums(kChunks, std::vector<double>(kSlots * kSuns));
    tbb::parallel_for(0, kChunks, [&](int chunk) {
      Random random{0x5EED0000ull + 1000003ull * static_cast<uint64_t>(chunk) + 7919ull * static_cast<uint64_t>(bin) +
                    104729ull * static_cast<uint64_t>(view_index)};
      std::vector<double>& sums = chunk_sums[static_cast<size_t>(chunk)];
      std::vector<double> physical(kSlots * kSuns), isotropic(kSuns);
      for (int path = 0; path < kPathsPerChunk; ++path) {
        std::fill(physical.begin(), physical.end(), 0.0);
        std::fill(isotropic.begin(), isotropic.end(), 0.0);
        const double u_cosine = (path % kStrataCosine + random.uniform()) / kStrataCosine;
        const double u_azimuth = (path / kStrataCosine + random.uniform()) / kStrataAzimuth;
        trace(bin, view, u_cosine, u_azimuth, random, physical, isotropic);
        for (int s = 0; s < kSuns; ++s) {
          const size_t base = static_cast<size_t>(s) * kSlots;
          double multiple = 0;
          for (int k = 1; k <= kMaxOrder; ++k) {
            sums[base + k] += physical[base + k];
            if (k >= 2) multiple += physical[base + k];
          }
          sums[base + kMaxOrder + 1] += multiple;
          sums[base + kMaxOrder + 2] += physical[base + 1] + multiple;
          sums[base + kMaxOrder + 3] += isotropic[static_cast<size_t>(s)];
          sums[base + kMaxOrder + 4] += physical[base + 1] + isotropic[static_cast<size_t>(s)];
          for (int k = 6; k <= kMaxOrder; ++k) sums[base + kMaxOrder + 5] += physical[base + k];
        }
      }
    });
    auto estimate = [&](size_t slot) { return estimate_from_chunks(chunk_sums, slot, kPathsPerChunk); };
    ViewResult result;
    for (int s = 0; s < kSuns; ++s) {
      const size_t base = static_cast<size_t>(s) * kSlots;
      for (int k = 1; k <= kMaxOrder; ++k) result.order[s][k] = estimate(base + k);
      result.multiple[s] = estimate(base + kMaxOrder + 1);
      result.total[s] = estimate(base + kMaxOrder + 2);
      result.multiple_isotropic[s] = estimate(base + kMaxOrder + 3);
      result.total_isotropic[s] = estimate(base + kMaxOrder + 4);
      result.tail[s] = estimate(base + kMaxOrder + 5);
    }
    return result;
  }

 private:
  // The mixed phase function at a point with Rayleigh and aerosol scattering coefficients.
  double phase(double sigma_r, double sigma_a, double cos_theta) const {
    const double p_a = aerosol_phase_(cos_theta);
    return (sigma_r * rayleigh_phase(cos_theta, atmosphere_.medium().rayleigh_gamma) + sigma_a * p_a) /
           (sigma_r + sigma_a);
  }

  // One backward path; adds the physical contribution of each order to physical[sun·slots
  // + order] and the contribution of orders ≥ 2 with isotropic scattering after the
  // first event to isotropic[sun]. (u_cosine, u_azimuth) choose the first direction on
  // the horizontal plane.
  void trace(int bin, const View& view, double u_cosine, double u_azimuth, Random& random,
             std::vector<double>& physical, std::vector<double>& isotropic) const {
    const AtmosphereMedium& m = atmosphere_.medium();
    const TransmittanceTable& transmittance = atmosphere_.transmittance();
    const double rg = transmittance.ground_radius(), rt = transmittance.top_radius();
    const double g = atmosphere_.settings().aerosol.asymmetry, albedo = atmosphere_.settings().ground_albedo;
    const double beta_r = m.rayleigh_scattering[bin], beta_as = m.aerosol_scattering[bin];
    const double beta_ae = m.aerosol_extinction[bin], beta_o = m.ozone_absorption[bin];
    // Every density is at most 1 where its coefficient is given, Rayleigh's at the
    // site's ground (sea level or above).
    const double majorant = beta_r * m.rayleigh_density(m.site_elevation_m) + beta_ae + beta_o;

    std::array<Vec3, kSuns> suns;
    for (int s = 0; s < kSuns; ++s) suns[s] = direction_from_sun_frame(kSunElevationsDeg[s], 0.0);
    Vec3 p{0, 0, rg}, w;
    double weight = 1.0, weight_iso = 1.0;
    if (view.horizontal_plane) {
      w = around({0, 0, 1}, std::sqrt(u_cosine), 2.0 * kPi * u_azimuth);
      weight = weight_iso = kPi;  // E = π · mean of L over cosine-distributed directions
    } else {
      w = direction_from_sun_frame(view.elevation_deg, view.azimuth_from_sun_deg);
    }
    for (int order = 1; order <= kMaxOrder; ++order) {
      const double r = length(p), mu = dot(p, w) / r;
      const bool ground = shell::hits_ground(r, mu, rg);
      const double t_max = ground ? shell::distance_to_ground(r, mu, rg) : shell::distance_to_outer_sphere(r, mu, rt);
      auto altitude_at = [&](double t) { return length(p + w * t) - m.earth_radius_m; };
      auto extinction_at = [&](double t) {
        const double h = altitude_at(t);
        return beta_r * m.rayleigh_density(h) + beta_ae * m.aerosol_density(h) + beta_o * m.ozone_density(h);
      };
      if (const std::optional<double> t = next_collision(t_max, majorant, random, extinction_at)) {
        const double h = altitude_at(*t), sigma_t = extinction_at(*t);
        const double sigma_r = beta_r * m.rayleigh_density(h), sigma_a = beta_as * m.aerosol_density(h);
        p = p + w * *t;
        const double sigma_s = sigma_r + sigma_a;
        weight *= sigma_s / sigma_t;
        weight_iso *= sigma_s / sigma_t;
        const double r_p = length(p);
        for (int s = 0; s < kSuns; ++s) {
          const float sun = transmittance.sun(r_p, dot(p, suns[s]) / r_p)[bin];
          if (sun <= 0) continue;
          physical[static_cast<size_t>(s) * kSlots + order] += weight * phase(sigma_r, sigma_a, dot(w, suns[s])) * sun;
          if (order >= 2) isotropic[static_cast<size_t>(s)] += weight_iso / kFourPi * sun;
        }
        // Next direction: light arriving from w_next scatters into −w, at cos θ = w·w_next.
        const double cos_theta =
            random.uniform() < 0.5 ? sample_henyey_greenstein(g, random.uniform()) : 1.0 - 2.0 * random.uniform();
        const Vec3 next = around(w, cos_theta, 2.0 * kPi * random.uniform());
        const double c = dot(w, next);
        const double pdf = 0.5 * henyey_greenstein_phase(c, g) + 0.5 / kFourPi;
        weight *= phase(sigma_r, sigma_a, c) / pdf;
        weight_iso *= (1.0 / kFourPi) / pdf;
        w = next;
      } else if (ground) {
        p = normalize(p + w * t_max) * rg;
        const Vec3 n = normalize(p);
        for (int s = 0; s < kSuns; ++s) {
          const double cos_sun = dot(n, suns[s]);
          if (cos_sun <= 0) continue;
          const double lit = albedo / kPi * cos_sun * transmittance.sun(rg, cos_sun)[bin];
          physical[static_cast<size_t>(s) * kSlots + order] += weight * lit;
          if (order >= 2) isotropic[static_cast<size_t>(s)] += weight_iso * lit;
        }
        // Cosine-weighted: BRDF·cos/pdf = albedo. The two numbers are drawn in separate
        // statements: as two arguments of one call their order was the compiler's (GCC
        // took them right to left, Clang left to right), and so were the paths and the
        // result. Azimuth first, as GCC did, so the numbers quoted above still hold.
        const double u_phi = random.uniform();
        const double u_cos = random.uniform();
        w = around(n, std::sqrt(u_cos), 2.0 * kPi * u_phi);
        weight *= albedo;
        weight_iso *= albedo;
      } else {
        break;  // left the atmosphere
      }
      if (order >= 2) {
        const double survive = std::min(1.0, std::max(weight, weight_iso));
        if (random.uniform() >= survive) break;
        weight /= survive;
        weight_iso /= survive;
      }
    }
  }

  const Atmosphere& atmosphere_;
  AerosolPhaseFunction aerosol_phase_;
};

// The model's radiance for a view, or its diffuse horizontal irradiance by a midpoint
// rule in elevation (weight sin e cos e) and azimuth (mirrored: the integrator depends
// on ν only). Against 64 × 128 directions with 200 segments this grid is within 0.1 %
// for a high sun and 0.7 % at sun 4° (the aureole near the horizon), small beside the
// differences it is used to measure.
double model_value(const ScatteringIntegrator& integrator, double rg, int bin, const View& view,
                   double sun_elevation_deg) {
  if (!view.horizontal_plane)
    return test_reference::integrated_radiance(integrator, rg, sun_elevation_deg, view.elevation_deg,
                                               view.azimuth_from_sun_deg, 400)[bin];
  constexpr int kElevation = 16, kAzimuth = 32, kSegments = 64;
  std::array<double, kElevation> rows{};
  tbb::parallel_for(0, kElevation, [&](int z) {
    const double e = 0.5 * kPi * (z + 0.5) / kElevation;
    for (int a = 0; a < kAzimuth; ++a)
      rows[static_cast<size_t>(z)] += std::sin(e) * std::cos(e) *
                                      test_reference::integrated_radiance(integrator, rg, sun_elevation_deg, degrees(e),
                                                                          180.0 * (a + 0.5) / kAzimuth, kSegments)[bin];
  });
  double sum = 0;
  for (double row : rows) sum += row;
  return sum * (0.5 * kPi / kElevation) * (2.0 * kPi / kAzimuth);
}

// The suns the sunlit-line estimator (sunlit_line_sky.h) traces, as indices into
// kSunElevationsDeg: 10° and 0°, where the collision estimator converges, to check one
// against the other; −4° and −8°, where it does not.
constexpr std::array<int, 4> kLineSuns{2, 4, 5, 6};

// The sunlit-line estimator's orders per sun of kLineSuns.
struct LineResult {
  std::array<Estimate, kLineSuns.size()> first, multiple;
};

// 64 chunks of 50 × 64 strata of the first direction (used by the horizontal plane):
// four times the collision estimator's paths, because at −8° its standard error at
// 25 × 32 (3.8–15 %) was as large as the difference sought, and heavy-tailed: the zenith
// at 450 nm read 17 points darker than with 16 times the paths, at a σ of 3.8 %.
LineResult run_line_estimator(const test_reference::SunlitLineSky& sky, int bin, int view_index) {
  constexpr int kStrataCosine = 50, kStrataAzimuth = 64, kPaths = kStrataCosine * kStrataAzimuth;
  constexpr size_t kStride = test_reference::SunlitLineSky::kSlotsPerSun;
  const View& view = kViews[static_cast<size_t>(view_index)];
  const size_t suns = sky.suns();
  std::vector<std::vector<double>> chunk_sums(kChunks, std::vector<double>(2 * suns));
  tbb::parallel_for(0, kChunks, [&](int chunk) {
    Random random{0x11E50000ull + 1000003ull * static_cast<uint64_t>(chunk) + 7919ull * static_cast<uint64_t>(bin) +
                  104729ull * static_cast<uint64_t>(view_index)};
    std::vector<double>& sums = chunk_sums[static_cast<size_t>(chunk)];
    std::vector<double> tally(kStride * suns);
    for (int path = 0; path < kPaths; ++path) {
      std::fill(tally.begin(), tally.end(), 0.0);
      const double u_cosine = (path % kStrataCosine + random.uniform()) / kStrataCosine;
      const double u_azimuth = (path / kStrataCosine + random.uniform()) / kStrataAzimuth;
      sky.trace(bin, view, u_cosine, u_azimuth, random, tally);
      for (size_t s = 0; s < suns; ++s) {
        sums[2 * s] += tally[s * kStride + 1];
        for (size_t k = 2; k < kStride; ++k) sums[2 * s + 1] += tally[s * kStride + k];
      }
    }
  });
  LineResult result;
  for (size_t s = 0; s < suns; ++s) {
    result.first[s] = estimate_from_chunks(chunk_sums, 2 * s, kPaths);
    result.multiple[s] = estimate_from_chunks(chunk_sums, 2 * s + 1, kPaths);
  }
  return result;
}

struct MonteCarloResults {
  std::array<std::array<ViewResult, kViews.size()>, 2> views;  // [blue, red][view]
  std::array<std::array<LineResult, kViews.size()>, 2> line;   // the same, sunlit-line estimator
};

// Prints the measurements quoted above when SKYLIT_REPORT is set (run
// --gtest_filter=MultipleScattering.* with SKYLIT_REPORT=1; printed by the first test
// that reads the sunlit-line estimator).
void print_report(const MonteCarloResults& mc);

const Atmosphere& monte_carlo_atmosphere() {
  static const Atmosphere atmosphere(AtmosphereSettings{}, monte_carlo_bands());
  return atmosphere;
}

// The collision estimator's results and the models' values; with `with_line` also the
// sunlit-line estimator's, traced only for the tests that read them: at four times the
// collision estimator's paths it takes about 20 s on two threads, which the tests of
// the collision estimator alone need not pay (each runs in its own process under CTest).
const MonteCarloResults& monte_carlo(bool with_line = false) {
  static MonteCarloResults results = [] {
    const Atmosphere& atmosphere = monte_carlo_atmosphere();
    AtmosphereSettings hillaire_settings;
    hillaire_settings.multiple_scattering = MultipleScatteringMethod::hillaire;
    static const Atmosphere hillaire(hillaire_settings, monte_carlo_bands());
    const AtmosphereSettings& settings = atmosphere.settings();
    const ScatteringIntegrator single(atmosphere.medium(), atmosphere.transmittance(), nullptr, nullptr,
                                      settings.aerosol, settings.ground_albedo);
    const MonteCarloSky sky(atmosphere);
    MonteCarloResults r;
    for (int b = 0; b < 2; ++b) {
      const int bin = b == 0 ? kBlue : kRed;
      for (size_t v = 0; v < kViews.size(); ++v) {
        ViewResult& result = r.views[b][v] = sky.run(bin, static_cast<int>(v));
        for (int s = 0; s < kSuns; ++s) {
          result.model_single[s] =
              model_value(single, atmosphere.ground_radius(), bin, kViews[v], kSunElevationsDeg[s]);
          result.model_full[s] =
              model_value(atmosphere.integrator(), atmosphere.ground_radius(), bin, kViews[v], kSunElevationsDeg[s]);
          result.model_hillaire[s] =
              model_value(hillaire.integrator(), hillaire.ground_radius(), bin, kViews[v], kSunElevationsDeg[s]);
        }
      }
    }
    return r;
  }();
  static bool line_traced = false;
  if (with_line && !line_traced) {
    std::vector<double> line_suns;
    for (int s : kLineSuns) line_suns.push_back(kSunElevationsDeg[static_cast<size_t>(s)]);
    const test_reference::SunlitLineSky line_sky(monte_carlo_atmosphere(), line_suns);
    for (int b = 0; b < 2; ++b)
      for (size_t v = 0; v < kViews.size(); ++v)
        results.line[b][v] = run_line_estimator(line_sky, b == 0 ? kBlue : kRed, static_cast<int>(v));
    line_traced = true;
    if (std::getenv("SKYLIT_REPORT")) print_report(results);
  }
  return results;
}

const char* bin_name(int b) { return b == 0 ? "450 nm" : "650 nm"; }

TEST(MultipleScattering, TransferFactorIsBetweenZeroAndOneAtAllAltitudes) {
  // f_ms is the fraction of isotropic light that one more scattering returns to a
  // point: the geometric series 1 + f + f² + … converges only for f < 1, and f > 0
  // wherever there is air to scatter.
  const Atmosphere& atmosphere = test_reference::default_atmosphere();
  const double rg = atmosphere.ground_radius();
  for (double height : {0.0, 500.0, 2e3, 8e3, 20e3, 40e3, 70e3, 99e3}) {
    for (double mu_sun : {1.0, 0.5, 0.1, 0.0, -0.3}) {
      const MultipleScatteringTable::Factors f = MultipleScatteringTable::factors_at(
          atmosphere.medium(), atmosphere.transmittance(), atmosphere.settings().ground_albedo, rg + height, mu_sun);
      for (int k = 0; k < kSpectralBins; ++k) {
        EXPECT_GT(f.transfer[k], 0.0f) << height << " m, mu_s " << mu_sun << ", bin " << k;
        EXPECT_LT(f.transfer[k], 1.0f) << height << " m, mu_s " << mu_sun << ", bin " << k;
        EXPECT_GE(f.second_order[k], 0.0f);
      }
      // More scattering in the blue (Rayleigh's λ^−4): more light comes back.
      EXPECT_GT(f.transfer[0], f.transfer[kSpectralBins - 1]) << height;
    }
  }
  // At the ground the air above returns a good part of what it scatters: measured 0.33
  // at 385 nm (Rayleigh τ ≈ 0.4 plus aerosols 0.16) and 0.09 at 775 nm; far from both
  // 0 and 1.
  const MultipleScatteringTable::Factors ground = MultipleScatteringTable::factors_at(
      atmosphere.medium(), atmosphere.transmittance(), atmosphere.settings().ground_albedo, rg, 0.5);
  EXPECT_GT(ground.transfer[0], 0.1f);
  EXPECT_LT(ground.transfer[0], 0.6f);
}

TEST(MultipleScattering, MonteCarloFirstOrderMatchesSingleScattering) {
  // The path tracer's first order and the integrator's single scattering (the model
  // without Ψ_ms) are two computations of the same integral. Tolerance: 4 standard
  // errors of the Monte Carlo mean (a false alarm once in ~16,000 comparisons) plus
  // 1 % for the integrator's quadrature (400 segments agree with 3,200 within 0.02 %
  // for a sun above the horizon and 0.5 % at −4°, where the Earth's shadow crosses the
  // ray; the horizontal plane's 16 × 32 directions are within 0.7 % of 64 × 128).
  // Not at −8° (the last sun): there few backward paths reach the sunlit air, and in
  // some views none of the 51,200 does.
  const MonteCarloResults& mc = monte_carlo();
  for (int b = 0; b < 2; ++b)
    for (size_t v = 0; v < kViews.size(); ++v)
      for (int s = 0; s + 1 < kSuns; ++s) {
        const ViewResult& r = mc.views[b][v];
        const Estimate& first = r.order[s][1];
        EXPECT_NEAR(first.mean, r.model_single[s], 4.0 * first.standard_error + 0.01 * r.model_single[s])
            << bin_name(b) << ", " << kViews[v].name << ", sun " << kSunElevationsDeg[s] << " deg";
      }
}

TEST(MultipleScattering, OrdersFallGeometricallyAndConverge) {
  const MonteCarloResults& mc = monte_carlo();
  for (int b = 0; b < 2; ++b)
    for (size_t v = 0; v < kViews.size(); ++v)
      for (int s = 0; s < 4; ++s) {  // suns above the horizon
        const ViewResult& r = mc.views[b][v];
        const auto& o = r.order[s];
        const std::string where = std::string(bin_name(b)) + ", " + kViews[v].name + ", sun " +
                                  std::to_string(static_cast<int>(kSunElevationsDeg[s])) + " deg";
        // From order 2 on each order is less than 0.6 of the one before. The clear
        // sky's vertical optical depth is ~0.35 at 450 nm and ~0.13 at 650 nm, so a
        // scattered photon scatters again with probability well under one half except
        // on long, low paths (measured ratios 0.07–0.53); 2σ of both estimates allow
        // for the noise of the higher orders.
        for (int k = 2; k <= 5; ++k)
          EXPECT_LT(o[k + 1].mean, 0.6 * o[k].mean + 2.0 * (o[k + 1].standard_error + o[k].standard_error))
              << where << ", order " << k + 1;
        // The series converges: orders ≥ 6 add little. Measured: at most 0.4 % of the
        // total at 650 nm; at 450 nm 0.3–1.3 % at the zenith, toward the sun and on the
        // horizontal plane, up to 2.3 % for low views (long paths through the dense air
        // near the ground). Bounds: 1 % at 650 nm, 3 % at 450 nm, each plus 3σ of the
        // tail's own Monte Carlo error.
        const double bound = (b == 0 ? 0.03 : 0.01) * r.total[s].mean;
        EXPECT_LT(r.tail[s].mean, bound + 3.0 * r.tail[s].standard_error) << where;
      }
}

// The model's total against single scattering (the model's own, which the path
// tracer's first order matches, above) plus the path tracer's orders ≥ 2: the
// comparison of the totals without the noise of the first order, which is most of
// the Monte Carlo noise. Relative to that total, with its standard error.
struct TotalDifference {
  double relative, standard_error;
};
// `hillaire`: the model with Hillaire's approximation, else with scattering orders.
TotalDifference total_difference(const ViewResult& r, int sun, bool isotropic_higher_orders, bool hillaire) {
  const Estimate& multiple = isotropic_higher_orders ? r.multiple_isotropic[sun] : r.multiple[sun];
  const double reference = r.model_single[sun] + multiple.mean;
  const double model = hillaire ? r.model_hillaire[sun] : r.model_full[sun];
  return {model / reference - 1.0, multiple.standard_error / reference};
}

std::string describe(int b, size_t v, int s) {
  return std::string(bin_name(b)) + ", " + kViews[v].name + ", sun " +
         std::to_string(static_cast<int>(kSunElevationsDeg[s])) + " deg";
}

TEST(MultipleScattering, HillaireMatchesMonteCarloUnderItsIsotropicAssumption) {
  // Hillaire's approximation is exact for order 2 and geometric after it if every
  // scattering after the first is isotropic; the path tracer's second throughput makes
  // that assumption. What remains is the implementation: f_ms's local, ground-free
  // energy transfer and the table's quadrature. Measured (issue 15's aerosol and
  // table): the model's total within −2.8 … +2.2 % for every view and sun above the
  // horizon (before: low by 0.4–6 %); the tolerance is 8 % of the total plus 4σ of the
  // Monte Carlo part (σ = 0.1–1.2 %).
  const MonteCarloResults& mc = monte_carlo();
  for (int b = 0; b < 2; ++b)
    for (size_t v = 0; v < kViews.size(); ++v)
      for (int s = 0; s < 4; ++s) {
        const TotalDifference d = total_difference(mc.views[b][v], s, true, true);
        EXPECT_LT(std::abs(d.relative), 0.08 + 4.0 * d.standard_error) << describe(b, v, s);
      }
}

TEST(MultipleScattering, TwilightMatchesMonteCarloUnderTheIsotropicAssumption) {
  // Sun 4° below the horizon: the multiply scattered light comes from air lit far off,
  // and Ψ_ms changes by orders of magnitude across the terminator. Its table holds
  // log Ψ_ms in 40 rows of μ_s: measured within −19 … +5 % of the isotropic paths
  // (each within 2.3σ; σ = 1.5–8.8 %). With Ψ_ms linear in 20 rows the model was
  // +8 … +53 % (650 nm, 10° away from the sun: +52.8 ± 5.0 %). Tolerance 6 % + 3σ.
  const MonteCarloResults& mc = monte_carlo();
  const int twilight = kTwilight;
  for (int b = 0; b < 2; ++b)
    for (size_t v = 0; v < kViews.size(); ++v) {
      const TotalDifference d = total_difference(mc.views[b][v], twilight, true, true);
      EXPECT_LT(std::abs(d.relative), 0.06 + 3.0 * d.standard_error) << describe(b, v, twilight);
    }
}

TEST(MultipleScattering, HillaireMatchesMonteCarloOnTheHorizontalPlaneAndAtTheZenith) {
  // The physics: anisotropic scattering at every order. Hillaire's isotropic higher
  // orders put the multiply scattered light in the wrong directions (see the top of
  // this file: −21 % … +28 % in single directions), but roughly conserve it, so the
  // irradiance on the horizontal plane, and the zenith (far from the aureole, at
  // mid-range scattering angles), stay close for a high sun. Measured at sun 60°
  // (issue 15's aerosol and table): horizontal plane +4.3 % (450 nm) and +7.4 %
  // (650 nm), zenith +4.4 % and +5.7 %; at sun 30°: horizontal plane −1.1 % and +2.4 %
  // (the zenith at 650 nm is +13 %).
  // (Before f_ms took in the ground's reflection of multiply scattered light, commit
  // e165070, the model was about 3 % lower: +0.1/+4.5 %, +2.4/+3.8 % and −5.5/0.0 %,
  // against which a 5 % bound at 60° was set. It left +7.1 % a hair under 5 % + 4σ,
  // so which equally valid set of paths the compiler's argument order picked, see
  // trace(), decided the result: Clang's gave +7.55 % against 6.94 %.)
  // Tolerances: 8 % at 60°, 7 % at 30° (the plane only), each plus 4σ of the Monte
  // Carlo part (σ = 0.4–0.7 %).
  const MonteCarloResults& mc = monte_carlo();
  const size_t zenith = 0, plane = kViews.size() - 1;
  for (int b = 0; b < 2; ++b) {
    for (size_t v : {zenith, plane}) {
      const TotalDifference d = total_difference(mc.views[b][v], 0, false, true);
      EXPECT_LT(std::abs(d.relative), 0.08 + 4.0 * d.standard_error) << describe(b, v, 0);
    }
    const TotalDifference d = total_difference(mc.views[b][plane], 1, false, true);
    EXPECT_LT(std::abs(d.relative), 0.07 + 4.0 * d.standard_error) << describe(b, plane, 1);
  }
}

TEST(MultipleScattering, ScatteringOrdersMatchMonteCarloInEveryView) {
  // The converged method against the physical paths (anisotropic scattering at every
  // order, the aerosol's own phase function): all six views (zenith, 45° toward and
  // away from the sun, 20° up at 90° from it, 10° up away from it, and the horizontal
  // plane), 450 and 650 nm, suns 60°, 30°, 10°, 4°, 0° and −4°. Measured in the US
  // Standard Atmosphere 1976 (2026-12-05, 48 sun cosines, three orders and the tail):
  // the total within −2.0 … +2.3 % by day (σ 0.2–1.4 %), −7.2 … +11.8 % at −4° (σ up
  // to 8.9 %); Hillaire's approximation was −17 … +27 % on the same paths. Tolerance: 5 % (issue 15) plus 3σ of the
  // Monte Carlo orders ≥ 2. At −8° these paths are too few to judge (σ up to 99 %, and views where their estimate is
  // far below the truth): the sunlit-line estimator's test below covers −4° and −8°.
  const MonteCarloResults& mc = monte_carlo();
  for (int s = 0; s <= kTwilight; ++s)
    for (int b = 0; b < 2; ++b)
      for (size_t v = 0; v < kViews.size(); ++v) {
        const TotalDifference d = total_difference(mc.views[b][v], s, false, false);
        EXPECT_LT(std::abs(d.relative), 0.05 + 3.0 * d.standard_error) << describe(b, v, s);
      }
}

// The model's total against its own single scattering plus the sunlit-line
// estimator's orders ≥ 2, as total_difference does with the collision estimator's.
TotalDifference line_total_difference(const MonteCarloResults& mc, int b, size_t v, size_t line_sun) {
  const int s = kLineSuns[line_sun];
  const ViewResult& r = mc.views[b][v];
  const Estimate& multiple = mc.line[b][v].multiple[line_sun];
  const double reference = r.model_single[s] + multiple.mean;
  return {r.model_full[s] / reference - 1.0, multiple.standard_error / reference};
}

// The sunlit-line estimator's three checks, run by one test (below) because CTest runs
// every test in a process of its own and the estimator's paths take about 50 s of CPU
// in each (2026-12-06: three tests took 105–111 s each under ctest -j2, a quarter of
// the suite's CPU).
void expect_sunlit_line_agrees_with_the_collision_estimator(const MonteCarloResults& mc) {
  // Two unbiased estimators of the same orders ≥ 2 from independent paths, at 10° and
  // 0° where the collision estimator converges: their difference is within 4 standard
  // errors of the difference (σ of both combined; a false alarm once in ~16,000
  // comparisons). Measured: within 2.0σ in all 24.
  for (size_t l = 0; l < 2; ++l)
    for (int b = 0; b < 2; ++b)
      for (size_t v = 0; v < kViews.size(); ++v) {
        const Estimate& collision = mc.views[b][v].multiple[kLineSuns[l]];
        const Estimate& line = mc.line[b][v].multiple[l];
        EXPECT_NEAR(line.mean, collision.mean, 4.0 * std::hypot(line.standard_error, collision.standard_error))
            << describe(b, v, kLineSuns[l]);
      }
}

void expect_sunlit_line_first_order_matches_single_scattering(const MonteCarloResults& mc) {
  // The estimator's first order (the expected collision along the view ray itself)
  // against the integrator's single scattering at every sun it traces, −8° included:
  // checks its sampling of the sunlit line. Tolerance as for the collision estimator's
  // first order: 4σ plus 1 % for the integrator's quadrature. Measured: within 0.6 %,
  // the horizontal plane at −8° +2.0/−2.8 % (σ 1.8/1.4 %).
  for (size_t l = 0; l < kLineSuns.size(); ++l)
    for (int b = 0; b < 2; ++b)
      for (size_t v = 0; v < kViews.size(); ++v) {
        const Estimate& first = mc.line[b][v].first[l];
        const double single = mc.views[b][v].model_single[kLineSuns[l]];
        EXPECT_NEAR(first.mean, single, 4.0 * first.standard_error + 0.01 * single) << describe(b, v, kLineSuns[l]);
      }
}

void expect_scattering_orders_match_the_sunlit_line_at_twilight(const MonteCarloResults& mc) {
  // Issue 15: the scattering orders within 5 % of the Monte Carlo reference over the
  // dome, here at −4° and −8° against the sunlit-line estimator (the collision
  // estimator's σ there is 2.2–9.7 % and up to 99 %). Tolerance: 5 % plus 2σ of its
  // orders ≥ 2 (the seeds are fixed: a result that passes keeps passing). Measured
  // (2026-12-05): −2.1 ± 0.7 … +0.4 ± 0.4 % at −4°, −7.1 ± 3.9 … +8.9 ± 2.8 % at −8°;
  // with four times these paths (819,200 per view, σ 1.0–2.6 %) every view at −8° is
  // within −2.7 … +5.2 %; with sixteen times (3,276,800, σ 0.5–1.2 %, 2026-12-06)
  // within −2.5 … +4.9 % (the zenith at 450 nm), and −4° within −2.1 … −0.1 %.
  // Equal bands of μ instead of the ones crowded toward the horizon and the poles failed
  // it: −12.0 ± 2.5 % at −8° (−13.3 ± 1.1 % with four times the paths).
  for (size_t l = 2; l < kLineSuns.size(); ++l)
    for (int b = 0; b < 2; ++b)
      for (size_t v = 0; v < kViews.size(); ++v) {
        const TotalDifference d = line_total_difference(mc, b, v, l);
        EXPECT_LT(std::abs(d.relative), 0.05 + 2.0 * d.standard_error) << describe(b, v, kLineSuns[l]);
      }
}

TEST(MultipleScattering, SunlitLineEstimatorChecksTheCollisionEstimatorAndTheModelAtTwilight) {
  const MonteCarloResults& mc = monte_carlo(true);
  {
    SCOPED_TRACE("orders >= 2 against the collision estimator at 10 and 0 deg");
    expect_sunlit_line_agrees_with_the_collision_estimator(mc);
  }
  {
    SCOPED_TRACE("first order against the integrator's single scattering");
    expect_sunlit_line_first_order_matches_single_scattering(mc);
  }
  {
    SCOPED_TRACE("the model's scattering orders at -4 and -8 deg");
    expect_scattering_orders_match_the_sunlit_line_at_twilight(mc);
  }
}

void print_report(const MonteCarloResults& mc) {
  for (int b = 0; b < 2; ++b)
    for (size_t v = 0; v < kViews.size(); ++v)
      for (int s = 0; s < kSuns; ++s) {
        const ViewResult& r = mc.views[b][v];
        const auto& o = r.order[s];
        double tail = 0;
        for (int k = 6; k <= kMaxOrder; ++k) tail += o[k].mean;
        const TotalDifference physical = total_difference(r, s, false, true),
                              isotropic = total_difference(r, s, true, true);
        const TotalDifference orders = total_difference(r, s, false, false);
        std::printf(
            "%s | %-28s | sun %3.0f | o1 %.4e ±%.2f%% vs single %+.2f%% | o2..o5 %.3e %.3e %.3e %.3e, >=6 %.2f%% | "
            "hillaire total vs MC %+.1f%% ±%.1f (ms %+.1f%%) | vs MC-iso %+.1f%% ±%.1f (ms %+.1f%%) | "
            "orders vs MC %+.1f%% ±%.1f (ms %+.1f%%)\n",
            bin_name(b), kViews[v].name, kSunElevationsDeg[s], o[1].mean, 100 * o[1].standard_error / o[1].mean,
            100 * (o[1].mean / r.model_single[s] - 1), o[2].mean, o[3].mean, o[4].mean, o[5].mean,
            100 * tail / r.total[s].mean, 100 * physical.relative, 100 * physical.standard_error,
            100 * ((r.model_hillaire[s] - r.model_single[s]) / r.multiple[s].mean - 1), 100 * isotropic.relative,
            100 * isotropic.standard_error,
            100 * ((r.model_hillaire[s] - r.model_single[s]) / r.multiple_isotropic[s].mean - 1), 100 * orders.relative,
            100 * orders.standard_error, 100 * ((r.model_full[s] - r.model_single[s]) / r.multiple[s].mean - 1));
      }
  for (int b = 0; b < 2; ++b)
    for (size_t v = 0; v < kViews.size(); ++v)
      for (size_t l = 0; l < kLineSuns.size(); ++l) {
        const int s = kLineSuns[l];
        const ViewResult& r = mc.views[b][v];
        const LineResult& line = mc.line[b][v];
        const TotalDifference orders = line_total_difference(mc, b, v, l);
        std::printf(
            "line %s | %-28s | sun %3.0f | o1 %.4e ±%.2f%% vs single %+.2f%% | ms %.4e ±%.2f%% vs collision %.4e "
            "±%.2f%% (%+.1f sigma) | orders vs line %+.1f%% ±%.1f (ms %+.1f%%)\n",
            bin_name(b), kViews[v].name, kSunElevationsDeg[s], line.first[l].mean,
            100 * line.first[l].standard_error / line.first[l].mean, 100 * (line.first[l].mean / r.model_single[s] - 1),
            line.multiple[l].mean, 100 * line.multiple[l].standard_error / line.multiple[l].mean, r.multiple[s].mean,
            100 * r.multiple[s].standard_error / r.multiple[s].mean,
            (line.multiple[l].mean - r.multiple[s].mean) /
                std::hypot(line.multiple[l].standard_error, r.multiple[s].standard_error),
            100 * orders.relative, 100 * orders.standard_error,
            100 * ((r.model_full[s] - r.model_single[s]) / line.multiple[l].mean - 1));
      }
}

}  // namespace
}  // namespace skylit
