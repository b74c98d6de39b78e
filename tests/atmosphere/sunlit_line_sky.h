// A second Monte Carlo reference of the atmosphere's sky, for a sun below the horizon.
//
// The collision estimator (MonteCarloSky in multiple_scattering_test.cpp) adds the sun
// only where a backward path happens to scatter. With the sun 8° down the Earth's
// shadow reaches 63 km above the observer; nearly every collision is in the dense,
// shadowed air below, and the estimate rests on the few paths that scatter in the
// thin sunlit air (standard errors of 12–76 %, views with no such path at all).
//
// This estimator follows the same backward paths (observer, delta-tracked free flights,
// the same direction sampling, Lambertian ground, Russian roulette) but scores at each
// vertex x the expected value of the collision estimator at the next vertex along a
// line (x, v): up to t_max (the ground or the top of the atmosphere),
//   ∫₀^t_max T(x, x + tv) (σ_R P_R(v·s) + σ_A P_A(v·s)) T_sun(x + tv) dt
//     + T(x, x + t_max v) (albedo/π) cos θ_s T_sun  if the line ends on the ground,
// which is what the collision (with probability density σ_t T, weight σ_s/σ_t, and the
// mixed phase function) or the ground hit scores on average. Order 1 takes the view
// ray itself; at later vertices v is drawn, apart from the path's own next direction,
// from an equal mixture of that direction's density and a Henyey–Greenstein lobe
// (g = 0.75) about the horizon under the sun, where the sunlit air is lowest and
// densest at twilight, and weighted by the vertex's phase function (or the ground's
// BRDF) over the mixture's density. The integrand vanishes in the Earth's shadow, a
// cylinder of the ground's radius behind the Earth, so the line is sampled only on the
// rest: cut into cells there, each weighted by the integrand at its middle (90 %) and by
// its length (10 %, so that no sunlit point has zero density), with 8 samples
// stratified over that piecewise-constant density. T(x, x + tv) is estimated by ratio
// tracking (Novák, Selle & Jarosz 2014) against a majorant twice the densest extinction
// on each of 16 pieces of the line, so every factor is at least ½. Each step is an
// unbiased estimate of the one it replaces, so the estimator is unbiased; it scores
// every vertex from which the drawn line crosses sunlit air, which at −8° is most.
//
// Shared with the model, as for MonteCarloSky: the medium's coefficients and density
// profiles, the phase functions, and TransmittanceTable::sun for the sun (bent by
// refraction, as the model's is, so it reaches a little into the geometric shadow; the
// sampled cells reach 20 km into it: with 5 km the first order at −8° missed 4–17 % of
// the refracted light).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "monte_carlo_paths.h"
#include "sky_reference.h"
#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/phase_functions.h"
#include "skylit/atmosphere/shell_geometry.h"

namespace skylit::test_reference {

class SunlitLineSky {
 public:
  static constexpr int kMaxOrder = 30;
  // Tally slots per sun: orders 1..kMaxOrder at their own index (0 unused).
  static constexpr size_t kSlotsPerSun = kMaxOrder + 1;

  SunlitLineSky(const Atmosphere& atmosphere, std::vector<double> sun_elevations_deg)
      : atmosphere_(atmosphere), aerosol_phase_(atmosphere.settings().aerosol) {
    for (double e : sun_elevations_deg) suns_.push_back(direction_from_sun_frame(e, 0.0));
  }

  size_t suns() const { return suns_.size(); }

  // One backward path; adds its contribution of each order to
  // tally[sun · kSlotsPerSun + order]. (u_cosine, u_azimuth) choose the first
  // direction on the horizontal plane.
  void trace(int bin, const View& view, double u_cosine, double u_azimuth, Random& random,
             std::vector<double>& tally) const {
    const AtmosphereMedium& m = atmosphere_.medium();
    const TransmittanceTable& transmittance = atmosphere_.transmittance();
    const Coefficients k = coefficients(bin);
    const double rg = transmittance.ground_radius(), rt = transmittance.top_radius();
    const double g = atmosphere_.settings().aerosol.asymmetry, albedo = atmosphere_.settings().ground_albedo;
    const double majorant = k.rayleigh * m.rayleigh_density(m.site_elevation_m) + k.aerosol_extinction + k.ozone;

    Vec3 p{0, 0, rg}, w;
    double weight = 1.0;
    if (view.horizontal_plane) {
      w = around({0, 0, 1}, std::sqrt(u_cosine), 2.0 * kPi * u_azimuth);
      weight = kPi;
    } else {
      w = direction_from_sun_frame(view.elevation_deg, view.azimuth_from_sun_deg);
    }
    std::vector<std::pair<double, double>> steps;  // ratio tracking: (t, T̂ after t)
    // Order 1: the expected first collision along the view ray.
    score(bin, k, p, w, weight, 1, random, steps, tally);
    for (int order = 2; order <= kMaxOrder; ++order) {
      // The free flight to the next vertex: delta tracking, as MonteCarloSky's.
      const double r = length(p), mu = dot(p, w) / r;
      const bool ground = shell::hits_ground(r, mu, rg);
      const double t_max = ground ? shell::distance_to_ground(r, mu, rg) : shell::distance_to_outer_sphere(r, mu, rt);
      auto density_at = [&](double t) { return density(k, length(p + w * t) - m.earth_radius_m); };
      const std::optional<double> collision =
          next_collision(t_max, majorant, random, [&](double t) { return density_at(t).extinction; });
      const bool collided = collision.has_value();
      const double t = collision.value_or(t_max);
      const Density d = collided ? density_at(t) : Density{};
      const double sigma_r = d.rayleigh, sigma_a = d.aerosol_scattering, sigma_t = d.extinction;
      if (!collided && !ground) break;  // left the atmosphere
      const Vec3 w_in = w;
      const Vec3 n = collided ? Vec3{} : normalize(p + w * t_max);
      p = collided ? p + w * t : n * rg;
      if (collided) weight *= (sigma_r + sigma_a) / sigma_t;
      // What the vertex sends back toward w_in's origin from light arriving along v:
      // the mixed phase function, or the Lambertian ground's albedo/π cos.
      auto scattered = [&](const Vec3& v) {
        if (!collided) return albedo / kPi * std::max(0.0, dot(n, v));
        const double c = dot(w_in, v);
        return (sigma_r * rayleigh_phase(c, m.rayleigh_gamma) + sigma_a * aerosol_phase_(c)) / (sigma_r + sigma_a);
      };
      auto continuation_pdf = [&](const Vec3& v) {
        if (!collided) return std::max(0.0, dot(n, v)) / kPi;
        return 0.5 * henyey_greenstein_phase(dot(w_in, v), g) + 0.5 / kFourPi;
      };
      auto sample_continuation = [&] {
        if (!collided) {
          const double u_phi = random.uniform();
          const double u_cos = random.uniform();
          return around(n, std::sqrt(u_cos), 2.0 * kPi * u_phi);
        }
        const double cos_theta =
            random.uniform() < 0.5 ? sample_henyey_greenstein(g, random.uniform()) : 1.0 - 2.0 * random.uniform();
        return around(w_in, cos_theta, 2.0 * kPi * random.uniform());
      };

      // This order: the expected next vertex along a direction v drawn from an equal
      // mixture of the continuation's density and a lobe toward the horizon under the
      // sun (all suns share its azimuth), where the sunlit air lies low at twilight.
      const Vec3 up = normalize(p);
      const Vec3 horizon = normalize(kSunAzimuth - up * dot(kSunAzimuth, up));
      const Vec3 v = random.uniform() < 0.5 ? sample_continuation()
                                            : around(horizon, sample_henyey_greenstein(kLobeG, random.uniform()),
                                                     2.0 * kPi * random.uniform());
      const double pdf_v = 0.5 * continuation_pdf(v) + 0.5 * henyey_greenstein_phase(dot(v, horizon), kLobeG);
      const double f_v = scattered(v);
      if (f_v > 0) score(bin, k, p, v, weight * f_v / pdf_v, order, random, steps, tally);

      // The path goes on along its own direction, as MonteCarloSky's.
      w = sample_continuation();
      weight *= scattered(w) / continuation_pdf(w);
      const double survive = std::min(1.0, weight);
      if (random.uniform() >= survive) break;
      weight /= survive;
    }
  }

 private:
  struct Coefficients {
    double rayleigh, aerosol_scattering, aerosol_extinction, ozone;
  };
  struct Density {
    double rayleigh, aerosol_scattering, extinction;  // σ_R, σ_A, σ_t (m⁻¹)
  };
  static constexpr int kPieces = 16;  // of the line, each with its own majorant
  static constexpr int kCells = 16;   // of the sunlit part, for the sampling density
  static constexpr int kSamples = 8;  // stratified over the cells' density
  static constexpr double kShadowMarginM = 20e3;
  // The gathering lobe: Henyey–Greenstein about the horizon under the sun.
  static constexpr double kLobeG = 0.75;
  static constexpr Vec3 kSunAzimuth{1, 0, 0};

  // Adds weight × the expected contribution of the next vertex along (p, w), for
  // every sun, to the tally of `order`.
  void score(int bin, const Coefficients& k, const Vec3& p, const Vec3& w, double weight, int order, Random& random,
             std::vector<std::pair<double, double>>& steps, std::vector<double>& tally) const {
    const TransmittanceTable& transmittance = atmosphere_.transmittance();
    const double rg = transmittance.ground_radius(), rt = transmittance.top_radius();
    const double r = length(p), mu = dot(p, w) / r;
    const bool ground = shell::hits_ground(r, mu, rg);
    const double t_max = ground ? shell::distance_to_ground(r, mu, rg) : shell::distance_to_outer_sphere(r, mu, rt);
    ratio_track(k, p, w, r, mu, t_max, random, steps);
    const double albedo = atmosphere_.settings().ground_albedo;
    for (size_t s = 0; s < suns_.size(); ++s)
      tally[s * kSlotsPerSun + static_cast<size_t>(order)] +=
          weight * gathered(bin, k, suns_[s], p, w, t_max, ground, albedo, steps, random);
  }

  Coefficients coefficients(int bin) const {
    const AtmosphereMedium& m = atmosphere_.medium();
    return {m.rayleigh_scattering[bin], m.aerosol_scattering[bin], m.aerosol_extinction[bin], m.ozone_absorption[bin]};
  }

  Density density(const Coefficients& k, double altitude_m) const {
    const AtmosphereMedium& m = atmosphere_.medium();
    const double rho_a = m.aerosol_density(altitude_m);
    const double sigma_r = k.rayleigh * m.rayleigh_density(altitude_m);
    return {sigma_r, k.aerosol_scattering * rho_a,
            sigma_r + k.aerosol_extinction * rho_a + k.ozone * m.ozone_density(altitude_m)};
  }

  // Ratio tracking along (p, w) up to t_max: steps holds each tentative collision's
  // distance and the estimate of the transmittance beyond it. The line is cut into
  // pieces crowded toward its lowest point, which is one of their ends; the densities
  // of air and aerosol fall with height, so each piece's densest point is its lower end
  // (ozone's density is at most 1).
  void ratio_track(const Coefficients& k, const Vec3& p, const Vec3& w, double r, double mu, double t_max,
                   Random& random, std::vector<std::pair<double, double>>& steps) const {
    const double earth = atmosphere_.medium().earth_radius_m;
    steps.clear();
    const std::vector<double> bounds = shell::crowded_boundaries(t_max, -r * mu, kPieces);
    double transmittance = 1.0;
    for (size_t i = 0; i + 1 < bounds.size(); ++i) {
      const double lowest = std::min(shell::radius_at(r, mu, bounds[i]), shell::radius_at(r, mu, bounds[i + 1]));
      const Density densest = density(k, lowest - earth - 1.0);
      const double majorant = 2.0 * (densest.extinction + k.ozone);
      if (majorant <= 0) continue;
      for (double t = bounds[i];;) {
        t -= std::log(1.0 - random.uniform()) / majorant;
        if (t >= bounds[i + 1]) break;
        transmittance *= 1.0 - density(k, length(p + w * t) - earth).extinction / majorant;
        steps.emplace_back(t, transmittance);
      }
    }
  }

  static double transmittance_at(const std::vector<std::pair<double, double>>& steps, double t) {
    const auto after = std::upper_bound(steps.begin(), steps.end(), t,
                                        [](double x, const std::pair<double, double>& s) { return x < s.first; });
    return after == steps.begin() ? 1.0 : std::prev(after)->second;
  }

  // The parts of [0, t_max] outside the Earth's shadow for the sun s (narrowed by
  // kShadowMarginM: a superset of the sunlit line).
  static std::vector<std::pair<double, double>> sunlit_parts(const Vec3& p, const Vec3& w, double t_max, const Vec3& s,
                                                             double shadow_radius) {
    const double ps = dot(p, s), ws = dot(w, s);
    const Vec3 pp = p - s * ps, wp = w - s * ws;
    const double a = dot(wp, wp), b = dot(pp, wp), c = dot(pp, pp) - shadow_radius * shadow_radius;
    double lo = -1e300, hi = 1e300;  // where the line is inside the shadow's cylinder
    const std::vector<std::pair<double, double>> whole{{0.0, t_max}};
    if (a < 1e-12) {
      if (c > 0) return whole;
    } else {
      const double discriminant = b * b - a * c;
      if (discriminant <= 0) return whole;
      const double q = std::sqrt(discriminant);
      lo = (-b - q) / a;
      hi = (-b + q) / a;
    }
    // and behind the Earth: p·s + t w·s < 0.
    if (ws > 0)
      hi = std::min(hi, -ps / ws);
    else if (ws < 0)
      lo = std::max(lo, -ps / ws);
    else if (ps >= 0)
      return whole;
    lo = std::max(lo, 0.0);
    hi = std::min(hi, t_max);
    if (lo >= hi) return whole;
    std::vector<std::pair<double, double>> parts;
    if (lo > 0) parts.emplace_back(0.0, lo);
    if (hi < t_max) parts.emplace_back(hi, t_max);
    return parts;
  }

  // The integrand of the line's expected contribution at distance t (without the
  // ground's term).
  double integrand(int bin, const Coefficients& k, const Vec3& s, const Vec3& p, const Vec3& w, double t,
                   double phase_r, double phase_a, const std::vector<std::pair<double, double>>& steps) const {
    const Vec3 x = p + w * t;
    const double r = length(x);
    const float sun = atmosphere_.transmittance().sun(r, dot(x, s) / r)[bin];
    if (sun <= 0) return 0.0;
    const Density d = density(k, r - atmosphere_.medium().earth_radius_m);
    return transmittance_at(steps, t) * (d.rayleigh * phase_r + d.aerosol_scattering * phase_a) * sun;
  }

  double gathered(int bin, const Coefficients& k, const Vec3& s, const Vec3& p, const Vec3& w, double t_max,
                  bool ground, double albedo, const std::vector<std::pair<double, double>>& steps,
                  Random& random) const {
    const TransmittanceTable& transmittance = atmosphere_.transmittance();
    double sum = 0;
    if (ground) {
      const Vec3 n = normalize(p + w * t_max);
      const double cos_sun = dot(n, s);
      if (cos_sun > 0)
        sum += transmittance_at(steps, t_max) * albedo / kPi * cos_sun *
               transmittance.sun(transmittance.ground_radius(), cos_sun)[bin];
    }
    const std::vector<std::pair<double, double>> parts =
        sunlit_parts(p, w, t_max, s, transmittance.ground_radius() - kShadowMarginM);
    double sunlit_length = 0;
    for (const auto& [a, b] : parts) sunlit_length += b - a;
    if (sunlit_length <= 0) return sum;
    const double c = dot(w, s);
    const double phase_r = rayleigh_phase(c, atmosphere_.medium().rayleigh_gamma), phase_a = aerosol_phase_(c);

    // Cells over the sunlit parts (in proportion to their lengths, at least one each)
    // and their weights: the integrand at the middle times the length.
    struct Cell {
      double start, width, weight;
    };
    std::array<Cell, kCells + 2> cells{};
    size_t n = 0;
    double importance = 0;
    for (const auto& [a, b] : parts) {
      const int count = std::max(1, static_cast<int>(kCells * (b - a) / sunlit_length));
      for (int i = 0; i < count && n < cells.size(); ++i, ++n) {
        const double width = (b - a) / count, start = a + i * width;
        cells[n] = {start, width, width * integrand(bin, k, s, p, w, start + 0.5 * width, phase_r, phase_a, steps)};
        importance += cells[n].weight;
      }
    }
    // 90 % by the integrand, 10 % by length (all by length where no middle is lit).
    const double by_importance = importance > 0 ? 0.9 : 0.0;
    double total = 0;
    for (size_t i = 0; i < n; ++i) {
      cells[i].weight = (importance > 0 ? by_importance * cells[i].weight / importance : 0.0) +
                        (1.0 - by_importance) * cells[i].width / sunlit_length;
      total += cells[i].weight;
    }
    // Stratified samples of the piecewise-constant density: sample j in [j, j+1)/kSamples
    // of its cumulative distribution.
    size_t cell = 0;
    double below = 0;  // cumulative weight before `cell`
    for (int j = 0; j < kSamples; ++j) {
      const double u = (j + random.uniform()) / kSamples * total;
      while (cell + 1 < n && below + cells[cell].weight <= u) below += cells[cell++].weight;
      const Cell& chosen = cells[cell];
      const double fraction = std::clamp((u - below) / chosen.weight, 0.0, 1.0);
      const double t = chosen.start + fraction * chosen.width;
      const double pdf = chosen.weight / total / chosen.width;
      sum += integrand(bin, k, s, p, w, t, phase_r, phase_a, steps) / (pdf * kSamples);
    }
    return sum;
  }

  const Atmosphere& atmosphere_;
  AerosolPhaseFunction aerosol_phase_;
  std::vector<Vec3> suns_;
};

}  // namespace skylit::test_reference
