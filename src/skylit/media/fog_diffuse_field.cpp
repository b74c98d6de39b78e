// The fog's diffuse radiance field by δ-M discrete ordinates (fog_diffuse_field.h).
//
// Depth. τ' = (1 − ωf)·σ·c, c the fog's column from the top (m; FogLayer::column), so
// every bin shares the levels, placed in c: thin near both faces (where the sky's and the
// ground's light enters and the field changes over a fraction of an optical depth) and
// growing by a tenth of the distance to the nearer face inside, where the field is
// diffuse and smooth (by half of it deeper than kFineDepth, in absurdly thick fog).
//
// Characteristics. Along a stream of cosine μ across a layer of scaled depth Δ, with the
// source S (per unit scaled extinction) linear in depth between its values S_in at the
// level where the stream enters and S_out where it leaves, x = Δ/μ:
//     L_out = e^{−x}·L_in + (g(x) − e^{−x})·S_in + (1 − g(x))·S_out,   g(x) = (1 − e^{−x})/x,
// exact for a linear source, with weights ≥ 0 for any x (no oscillation in thick layers).
// For the field's Fourier term m in azimuth about the sunbeam (L = Σ_m L_m(τ, u)·cos mφ),
// S_m = ω'·Σ_t 2π w_t p'_m(u, u_t)·L_m,t + (2 − δ_m0)·ω'·p'_m(u, −μ0)·E0·e^{−τ'/μ0},
// p'_m = Σ_l (2l + 1)/4π·χ'_l·Λ_l^m(u)·Λ_l^m(u') the δ-M phase function's term m.
#include "skylit/media/fog_diffuse_field.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <tbb/parallel_for.h>

#include "skylit/core/angles.h"
#include "skylit/core/banded_matrix.h"

namespace skylit {
namespace {

constexpr int kN = FogDiffuseField::kStreams;
constexpr double kFineDepth = 32.0;  // scaled optical depth from the nearer face (see the levels)
constexpr int kStreamsAll = 2 * kN;

// P_0(u) … P_{count−1}(u).
std::vector<double> legendre(double u, int count) {
  std::vector<double> p(static_cast<size_t>(count), 0.0);
  p[0] = 1;
  if (count > 1) p[1] = u;
  for (int l = 2; l < count; ++l)
    p[static_cast<size_t>(l)] =
        ((2 * l - 1) * u * p[static_cast<size_t>(l - 1)] - (l - 1) * p[static_cast<size_t>(l - 2)]) / l;
  return p;
}

// The normalised associated Legendre functions Λ_l^m(u) = √((l−m)!/(l+m)!)·P_l^m(u) for
// l = 0 … count−1 (0 for l < m), without the Condon–Shortley phase, which cancels in the
// products Λ_l^m(u)·Λ_l^m(u') that the addition theorem needs:
//     P_l(cos Θ) = Σ_m (2 − δ_m0)·Λ_l^m(u)·Λ_l^m(u')·cos(m(φ − φ')).
// The recurrences are those of the normalised functions (stable for the l, m ≤ 2N here).
std::vector<double> associated_legendre(double u, int m, int count) {
  std::vector<double> p(static_cast<size_t>(count), 0.0);
  if (m >= count) return p;
  const double s = std::sqrt(std::max(0.0, 1 - u * u));
  double pmm = 1;  // Λ_m^m = √((2m)!)/(2^m m!)·s^m, built factor by factor
  for (int k = 1; k <= m; ++k) pmm *= std::sqrt((2.0 * k - 1) / (2.0 * k)) * s;
  p[static_cast<size_t>(m)] = pmm;
  if (m + 1 < count) p[static_cast<size_t>(m + 1)] = std::sqrt(2.0 * m + 1) * u * pmm;
  for (int l = m + 2; l < count; ++l) {
    const double a = (2.0 * l - 1) / std::sqrt(static_cast<double>(l * l - m * m));
    const double b = std::sqrt(static_cast<double>((l - 1) * (l - 1) - m * m) / static_cast<double>(l * l - m * m));
    p[static_cast<size_t>(l)] = a * u * p[static_cast<size_t>(l - 1)] - b * p[static_cast<size_t>(l - 2)];
  }
  return p;
}

// (1 − e^{−x})/x and e^{−x} for x ≥ 0, the characteristic's weights.
struct StepWeights {
  double through, entry, exit;  // e^{−x}, g − e^{−x}, 1 − g
};
StepWeights step_weights(double depth, double mu) {
  const double x = depth / mu;
  const double t = std::exp(-x);
  if (x < 1e-4) return {t, x / 2 - x * x / 3, x / 2 - x * x / 6};
  const double g = -std::expm1(-x) / x;
  return {t, g - t, 1 - g};
}

}  // namespace

void gauss_legendre_unit(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(static_cast<size_t>(n), 0.0);
  w.assign(static_cast<size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-15) break;
    }
    x[static_cast<size_t>(n - 1 - i)] = 0.5 * (1 + t);
    w[static_cast<size_t>(n - 1 - i)] = 1.0 / ((1 - t * t) * dp * dp);  // 2/((1−t²)P'²) halved
  }
}

std::vector<double> phase_legendre_moments(const std::function<double(double)>& phase, int count) {
  // χ_l = 2π ∫ p(x) P_l(x) dx on panels in y = 1 − x halving toward the forward
  // direction, 8 Gauss points each.
  std::vector<double> gx, gw;
  gauss_legendre_unit(8, gx, gw);
  std::vector<double> chi(static_cast<size_t>(count), 0.0);
  double hi = 2.0;
  for (int panel = 0; panel <= 44; ++panel) {
    const double lo = panel == 44 ? 0.0 : 0.5 * hi;
    for (size_t i = 0; i < gx.size(); ++i) {
      const double y = lo + (hi - lo) * gx[i], x = 1 - y;
      const double weight = 2 * kPi * (hi - lo) * gw[i] * phase(x);
      const std::vector<double> p = legendre(x, count);
      for (int l = 0; l < count; ++l) chi[static_cast<size_t>(l)] += weight * p[static_cast<size_t>(l)];
    }
    hi = lo;
  }
  return chi;
}

FogDiffuseField::FogDiffuseField(const FogLayer& layer, const FogLayerLighting& lighting)
    : layer_(layer), omega_(layer.single_scattering_albedo()) {
  // δ-M phase function.
  constexpr int kept = kStreamsAll;  // δ-M: the moments the streams can carry
  const std::vector<double> chi =
      phase_legendre_moments([&layer](double c) { return layer.phase(c); }, kStreamsAll + 1);
  f_ = std::clamp(chi[static_cast<size_t>(kept)], 0.0, 0.999);
  chi_scaled_.assign(kStreamsAll, 0.0);
  for (int l = 0; l < kept; ++l) chi_scaled_[static_cast<size_t>(l)] = (chi[static_cast<size_t>(l)] - f_) / (1 - f_);
  // p'_m(u, u') = Σ_l (2l + 1)/4π·χ'_l·Λ_l^m(u)·Λ_l^m(u'): Fourier term m of the δ-M
  // phase function between two cosines (m = 0: its azimuthal mean).
  auto phase_term = [&](const std::vector<double>& pa, const std::vector<double>& pb) {
    double sum = 0;
    for (int l = 0; l < kStreamsAll; ++l)
      sum += (2 * l + 1) / (4 * kPi) * chi_scaled_[static_cast<size_t>(l)] * pa[static_cast<size_t>(l)] *
             pb[static_cast<size_t>(l)];
    return sum;
  };
  const double depth_scale = 1 - omega_ * f_;
  const double omega_scaled = depth_scale > 0 ? omega_ * (1 - f_) / depth_scale : 0.0;

  // Streams: 0 … N−1 downward (upward cosine −μ), N … 2N−1 upward.
  std::vector<double> mu_node, w_node;
  gauss_legendre_unit(kN, mu_node, w_node);
  std::vector<double> mu(kStreamsAll), w(kStreamsAll), u(kStreamsAll);
  for (int s = 0; s < kStreamsAll; ++s) {
    mu[static_cast<size_t>(s)] = mu_node[static_cast<size_t>(s % kN)];
    w[static_cast<size_t>(s)] = w_node[static_cast<size_t>(s % kN)];
    u[static_cast<size_t>(s)] = s < kN ? -mu[static_cast<size_t>(s)] : mu[static_cast<size_t>(s)];
  }
  const double mu0 = lighting.sun_cosine;
  const bool sun = mu0 > 0 && !lighting.sun_irradiance.is_black();

  // Output directions: elevations ±90°·((k + 1)/K)², crowding toward the horizon (0.1°
  // apart there) and 5.6° apart at the zenith and nadir, where the terms m ≥ 1 vary as
  // sin^m θ (even spacing in the cosine would leave the top 20° to one interval).
  constexpr int kK = kDirectionsPerHemisphere;
  auto cosine = [](int k) { return std::sin(0.5 * kPi * std::pow((k + 1.0) / kK, 2)); };
  for (int k = kK - 1; k >= 0; --k) direction_.push_back(-cosine(k));
  for (int k = 0; k < kK; ++k) direction_.push_back(cosine(k));
  const size_t directions = direction_.size();

  // Levels in the column from the top, for the largest extinction of the bins.
  const double total = layer.column(layer.bottom_m(), 1.0, 0.0, layer.top_m() - layer.bottom_m());
  const auto& sigma = layer.unit_density_extinction_bins();
  const double sigma_max = *std::max_element(sigma.begin(), sigma.end());
  const double scale = depth_scale * sigma_max;  // τ' per metre of column
  const double depth = std::min(scale * total, 1e12);
  column_.push_back(0.0);
  if (depth > 0 && total > 0) {
    const double first = std::clamp(sun ? 0.1 * mu0 : 0.02, 0.005, 0.02);
    const double widest = std::max(1.0, depth / 128);
    double at = 0;
    while (at < depth) {
      const double nearer = std::min(at, depth - at);
      // Deeper than kFineDepth from both faces (only in fogs thicker than any real one)
      // the light has diffused: the field is linear in depth without absorption (which
      // the characteristics integrate exactly) and decays exponentially with it, so the
      // steps grow by half the distance instead of a tenth, without the cap `widest`.
      // A fog of density 1e250 then has 230 levels, not 640 (300 MB of tables and
      // seconds to build); fogs up to twice kFineDepth are not affected.
      const bool deep = nearer > kFineDepth;
      double step = std::min({first + (deep ? 0.5 : 0.1) * nearer, deep ? depth : widest, depth / 16});
      if (depth - at < 1.3 * step) step = depth - at;
      at += step;
      column_.push_back(at >= depth ? total : at / scale);
    }
  } else {
    column_.push_back(std::max(total, 0.0));
  }
  const int levels = static_cast<int>(column_.size()), layers = levels - 1;

  // The sky's Fourier terms in azimuth about the sunbeam, a_m(μ) = (2 − δ_m0)/2π ∫ L cos mφ dφ,
  // by the midpoint rule over the half circle (the sky is symmetric about the sun's
  // vertical plane), at the streams' and the output directions' cosines.
  constexpr int kSkyAzimuths = 4 * kModes;
  auto sky_terms = [&](double mu_down) {
    std::vector<Spectrum> terms(kModes, Spectrum(0.0f));
    for (int j = 0; j < kSkyAzimuths; ++j) {
      const double phi = (j + 0.5) * kPi / kSkyAzimuths;
      const Spectrum l = lighting.sky(mu_down, phi);
      for (int m = 0; m < kModes; ++m)
        terms[static_cast<size_t>(m)] +=
            l * static_cast<float>((m == 0 ? 1.0 : 2.0) * std::cos(m * phi) / kSkyAzimuths);
    }
    return terms;
  };
  std::vector<std::vector<Spectrum>> sky_node(kN), sky_out(directions);
  for (int s = 0; s < kN; ++s) sky_node[static_cast<size_t>(s)] = sky_terms(mu[static_cast<size_t>(s)]);
  for (size_t d = 0; d < directions; ++d)
    if (direction_[d] < 0) sky_out[d] = sky_terms(-direction_[d]);

  scattered_.assign(static_cast<size_t>(levels) * directions * kModes, Spectrum(0.0f));
  radiance_.assign(scattered_.size(), Spectrum(0.0f));
  without_sun_.assign(scattered_.size(), Spectrum(0.0f));
  downward_.assign(static_cast<size_t>(levels), Spectrum(0.0f));
  const double ground = std::clamp(lighting.ground_albedo, 0.0, 1.0) / kPi;

  // Bins of equal σ share one system per Fourier term (all of them for grey fog).
  std::map<double, std::vector<int>> groups;
  for (int b = 0; b < kSpectralBins; ++b) groups[sigma[static_cast<size_t>(b)]].push_back(b);
  const int n = kStreamsAll * levels;
  auto column_of = [](int level, int stream) { return kStreamsAll * level + stream; };
  // A term m ≥ 1 has a source only in the sun and in the sky's azimuthal structure
  // (without either, e.g. under a uniform sky, it is 0 and is not solved).
  // (The midpoint sums leave terms of ~1e-8 of the mean for a uniform sky.)
  auto has_term = [](const std::vector<Spectrum>& terms, int m) {
    for (int b = 0; b < kSpectralBins; ++b)
      if (std::abs(terms[static_cast<size_t>(m)][b]) > 1e-6f * std::abs(terms[0][b])) return true;
    return false;
  };
  auto sky_has_term = [&](int m) {
    for (const auto& terms : sky_node)
      if (has_term(terms, m)) return true;
    for (const auto& terms : sky_out)
      if (!terms.empty() && has_term(terms, m)) return true;
    return false;
  };
  for (int m = 0; m < kModes; ++m) {
    if (m > 0 && !sun && !sky_has_term(m)) continue;
    // Term m of the phase function at the streams, the sun and the output directions.
    std::vector<std::vector<double>> p_node;
    p_node.reserve(u.size());
    for (double us : u) p_node.push_back(associated_legendre(us, m, kStreamsAll));
    const std::vector<double> p_sun = associated_legendre(-std::max(mu0, 0.0), m, kStreamsAll);
    // The coupling ω'·2π·w_t·p'_m(u_s, u_t) (2π for every m: ∫cos m(φ−φ')·cos mφ' dφ' = π
    // meets the factor 2 of the addition theorem) and the sun's (2 − δ_m0)·ω'·p'_m(u_s, −μ0).
    const double sun_factor = m == 0 ? 1.0 : 2.0;
    std::vector<double> coupling(kStreamsAll * kStreamsAll), sun_coupling(kStreamsAll);
    for (int s = 0; s < kStreamsAll; ++s) {
      for (int t = 0; t < kStreamsAll; ++t)
        coupling[static_cast<size_t>(s * kStreamsAll + t)] =
            omega_scaled * 2 * kPi * w[static_cast<size_t>(t)] *
            phase_term(p_node[static_cast<size_t>(s)], p_node[static_cast<size_t>(t)]);
      sun_coupling[static_cast<size_t>(s)] =
          sun ? sun_factor * omega_scaled * phase_term(p_node[static_cast<size_t>(s)], p_sun) : 0.0;
    }
    // The output directions' coupling to the streams and to the sun.
    std::vector<double> out_coupling(directions * kStreamsAll), out_sun(directions);
    for (size_t d = 0; d < directions; ++d) {
      const std::vector<double> p_out = associated_legendre(direction_[d], m, kStreamsAll);
      for (int t = 0; t < kStreamsAll; ++t)
        out_coupling[d * kStreamsAll + static_cast<size_t>(t)] =
            2 * kPi * w[static_cast<size_t>(t)] * phase_term(p_out, p_node[static_cast<size_t>(t)]);
      out_sun[d] = sun ? sun_factor * omega_scaled * phase_term(p_out, p_sun) : 0.0;
    }

    for (const auto& [sigma_group, bins] : groups) {
      const double per_column = depth_scale * sigma_group;
      std::vector<double> tau(static_cast<size_t>(levels));
      for (int k = 0; k < levels; ++k)
        tau[static_cast<size_t>(k)] = std::min(per_column * column_[static_cast<size_t>(k)], 1e12);
      auto weights = [&](int k, double mu_s) {
        return step_weights(tau[static_cast<size_t>(k + 1)] - tau[static_cast<size_t>(k)], mu_s);
      };
      BandedMatrix a(n, 3 * kN - 1, 3 * kN - 1);
      for (int s = 0; s < kN; ++s) a.at(s, column_of(0, s)) = 1.0;  // the sky at the top
      for (int k = 0; k < layers; ++k) {
        for (int s = 0; s < kStreamsAll; ++s) {
          const int row = kN + kStreamsAll * k + s;
          const StepWeights sw = weights(k, mu[static_cast<size_t>(s)]);
          const bool down = s < kN;
          const int in = down ? k : k + 1, out = down ? k + 1 : k;
          a.at(row, column_of(out, s)) += 1.0;
          a.at(row, column_of(in, s)) -= sw.through;
          for (int t = 0; t < kStreamsAll; ++t) {
            const double c = coupling[static_cast<size_t>(s * kStreamsAll + t)];
            a.at(row, column_of(in, t)) -= sw.entry * c;
            a.at(row, column_of(out, t)) -= sw.exit * c;
          }
        }
      }
      // The Lambertian ground reflects the downward flux, into the azimuthal mean only.
      const double ground_m = m == 0 ? ground : 0.0;
      for (int s = kN; s < kStreamsAll; ++s) {
        const int row = kN + kStreamsAll * layers + (s - kN);
        a.at(row, column_of(layers, s)) += 1.0;
        for (int t = 0; t < kN; ++t)
          a.at(row, column_of(layers, t)) -=
              ground_m * 2 * kPi * w[static_cast<size_t>(t)] * mu[static_cast<size_t>(t)];
      }
      if (!a.factorise()) continue;  // cannot happen for ω' ≤ 1; the term stays 0

      for (int b : bins) {
        const double e0 = sun ? lighting.sun_irradiance[b] : 0.0;
        auto beam = [&](int k) { return sun ? e0 * std::exp(-tau[static_cast<size_t>(k)] / mu0) : 0.0; };
        std::vector<double> rhs(static_cast<size_t>(n), 0.0);
        for (int s = 0; s < kN; ++s)
          rhs[static_cast<size_t>(s)] = sky_node[static_cast<size_t>(s)][static_cast<size_t>(m)][b];
        for (int k = 0; k < layers; ++k)
          for (int s = 0; s < kStreamsAll; ++s) {
            const StepWeights sw = weights(k, mu[static_cast<size_t>(s)]);
            const bool down = s < kN;
            const int in = down ? k : k + 1, out = down ? k + 1 : k;
            rhs[static_cast<size_t>(kN + kStreamsAll * k + s)] =
                sun_coupling[static_cast<size_t>(s)] * (sw.entry * beam(in) + sw.exit * beam(out));
          }
        const double ground_direct = sun ? ground_m * mu0 * beam(layers) : 0.0;
        for (int s = kN; s < kStreamsAll; ++s)
          rhs[static_cast<size_t>(kN + kStreamsAll * layers + (s - kN))] = ground_direct;
        a.solve(rhs);
        // Terms m ≥ 1 change sign with azimuth; only the azimuthal mean is a radiance.
        auto node = [&](int k, int t) {
          const double v = rhs[static_cast<size_t>(column_of(k, t))];
          return m == 0 ? std::max(0.0, v) : v;
        };

        if (m == 0)
          for (int k = 0; k < levels; ++k) {
            double flux = 0;
            for (int t = 0; t < kN; ++t)
              flux += 2 * kPi * w[static_cast<size_t>(t)] * mu[static_cast<size_t>(t)] * node(k, t);
            downward_[static_cast<size_t>(k)][b] = static_cast<float>(flux);
          }
        const double ground_up =
            m == 0 ? ground * (downward_[static_cast<size_t>(layers)][b] + mu0 * beam(layers)) : 0.0;

        // Each output direction: its source at every level, its radiance by the formal
        // solution, and the light scattered toward it.
        std::vector<double> source(static_cast<size_t>(levels)), body(static_cast<size_t>(levels));
        std::vector<double> streams_source(static_cast<size_t>(levels));
        std::vector<double> l(static_cast<size_t>(levels)), diffuse_only(static_cast<size_t>(levels));
        for (size_t d = 0; d < directions; ++d) {
          const double uo = direction_[d], mu_o = std::abs(uo);
          for (int k = 0; k < levels; ++k) {
            double integral = 0;  // ∫ p'_m L_m over the streams
            for (int t = 0; t < kStreamsAll; ++t)
              integral += out_coupling[d * kStreamsAll + static_cast<size_t>(t)] * node(k, t);
            body[static_cast<size_t>(k)] = integral;
            streams_source[static_cast<size_t>(k)] = omega_scaled * integral;
            source[static_cast<size_t>(k)] = omega_scaled * integral + out_sun[d] * beam(k);
          }
          // The formal solution along the direction from its boundary: the sky at the
          // top for light travelling down, the ground's reflection at the bottom for up.
          const double boundary = uo < 0 ? sky_out[d][static_cast<size_t>(m)][b] : ground_up;
          auto formal_solution = [&](const std::vector<double>& src, std::vector<double>& out) {
            if (uo < 0) {
              out[0] = boundary;
              for (int k = 0; k < layers; ++k) {
                const StepWeights sw = weights(k, mu_o);
                out[static_cast<size_t>(k + 1)] = sw.through * out[static_cast<size_t>(k)] +
                                                  sw.entry * src[static_cast<size_t>(k)] +
                                                  sw.exit * src[static_cast<size_t>(k + 1)];
              }
            } else {
              out[static_cast<size_t>(layers)] = boundary;
              for (int k = layers - 1; k >= 0; --k) {
                const StepWeights sw = weights(k, mu_o);
                out[static_cast<size_t>(k)] = sw.through * out[static_cast<size_t>(k + 1)] +
                                              sw.entry * src[static_cast<size_t>(k + 1)] +
                                              sw.exit * src[static_cast<size_t>(k)];
              }
            }
          };
          formal_solution(source, l);
          // The forward spike returns the diffuse radiance along the view, but not the
          // sun's first scattering by p' in it: the beams carry the sun's single
          // scattering with the true phase function and the spike's light after it
          // (fog_sun_inscatter with k), and p' misplaces a sharp peak's light by tens of
          // degrees (Nakajima and Tanaka 1988's TMS correction).
          formal_solution(streams_source, diffuse_only);
          for (int k = 0; k < levels; ++k) {
            const size_t at = (static_cast<size_t>(k) * directions + d) * kModes + static_cast<size_t>(m);
            const double radiance = m == 0 ? std::max(0.0, l[static_cast<size_t>(k)]) : l[static_cast<size_t>(k)];
            const double scattered =
                f_ * diffuse_only[static_cast<size_t>(k)] + (1 - f_) * body[static_cast<size_t>(k)];
            radiance_[at][b] = static_cast<float>(radiance);
            scattered_[at][b] = static_cast<float>(m == 0 ? std::max(0.0, scattered) : scattered);
            const double unlit = diffuse_only[static_cast<size_t>(k)];
            without_sun_[at][b] = static_cast<float>(m == 0 ? std::max(0.0, unlit) : unlit);
          }
        }
      }
    }
  }
  if (sun) {
    sun_cosine_ = mu0;
    sun_side_.assign(scattered_.size(), Spectrum(0.0f));
    tabulate_sun_side(mu0);
  }
  // The largest light scattered toward any direction: bounded by Σ_m |S_m| per bin.
  for (size_t at = 0; at < scattered_.size(); at += kModes)
    for (int b = 0; b < kSpectralBins; ++b) {
      double bound = 0;
      for (int m = 0; m < kModes; ++m) bound += std::abs(scattered_[at + static_cast<size_t>(m)][b]);
      largest_[static_cast<size_t>(b)] = std::max(largest_[static_cast<size_t>(b)], bound);
    }
}

void FogDiffuseField::tabulate_sun_side(double mu0) {
  // The directions of travel within kSunSideDeg of the sunbeam's, s (upward cosine −μ0,
  // azimuth 0): Gauss–Legendre in the angle from s (p' has a forward lobe tens of degrees
  // wide, which even steps in the cosine would leave to one or two rings), even around.
  constexpr int kRings = 12, kAround = 24, kAzimuths = 2 * kModes;
  const double cone_angle = radians(kSunSideDeg);
  std::vector<double> ring_x, ring_w;
  gauss_legendre_unit(kRings, ring_x, ring_w);
  const Vec3 s{std::sqrt(std::max(0.0, 1 - mu0 * mu0)), 0.0, -mu0};
  const Vec3 side = normalize(std::abs(s.z) < 0.99 ? cross(s, Vec3{0, 0, 1}) : cross(s, Vec3{1, 0, 0}));
  const Vec3 third = cross(s, side);
  struct Node {
    Vec3 dir;
    double weight;  // solid angle (sr)
  };
  std::vector<Node> cone;
  for (int r = 0; r < kRings; ++r) {
    const double angle = cone_angle * ring_x[static_cast<size_t>(r)];
    const double c = std::cos(angle), sn = std::sin(angle);
    for (int a = 0; a < kAround; ++a) {
      const double psi = 2 * kPi * (a + 0.5) / kAround;
      cone.push_back({c * s + sn * (std::cos(psi) * side + std::sin(psi) * third),
                      cone_angle * ring_w[static_cast<size_t>(r)] * sn * 2 * kPi / kAround});
    }
  }
  // The weights (1 − f)·p'(ω_n·u)·dω_n toward each output direction and azimuth. (The
  // spike's f·D stays: it returns the light travelling along the view itself, which no
  // building blocks while the view passes; where the view ends on a surface, the
  // surface's own light replaces it, FogMedium::Along::forward_gain.)
  const size_t directions = direction_.size(), nodes = cone.size();
  std::vector<float> weight(directions * kAzimuths * nodes);
  for (size_t d = 0; d < directions; ++d)
    for (int i = 0; i < kAzimuths; ++i) {
      const double phi = (i + 0.5) * kPi / kAzimuths, up = direction_[d];
      const double horizontal = std::sqrt(std::max(0.0, 1 - up * up));
      const Vec3 u{horizontal * std::cos(phi), horizontal * std::sin(phi), up};
      const size_t at = d * kAzimuths + static_cast<size_t>(i);
      for (size_t n = 0; n < nodes; ++n)
        weight[at * nodes + n] = static_cast<float>((1 - f_) * smooth_phase(dot(cone[n].dir, u)) * cone[n].weight);
    }
  tbb::parallel_for(size_t{0}, column_.size(), [&](size_t k) {
    std::vector<Spectrum> arriving(nodes), sampled(kAzimuths);
    std::array<Spectrum, kModes> terms;
    // The diffuse radiance travelling along each node of the cone at this level.
    for (size_t n = 0; n < nodes; ++n) {
      const Vec3& w = cone[n].dir;
      radiance_terms_at_level(k, w.z, terms);
      const AzimuthTerms cosines = azimuth_terms(std::atan2(w.y, w.x));
      Spectrum v(0.0f);
      add_azimuth_weighted(v, terms.data(), kModes, cosines.data(), 1.0f);
      for (int b = 0; b < kSpectralBins; ++b) v[b] = std::max(v[b], 0.0f);
      arriving[n] = v;
    }
    for (size_t d = 0; d < directions; ++d) {
      for (int i = 0; i < kAzimuths; ++i) {
        const size_t at = d * kAzimuths + static_cast<size_t>(i);
        Spectrum sum(0.0f);
        for (size_t n = 0; n < nodes; ++n) sum += arriving[n] * weight[at * nodes + n];
        sampled[static_cast<size_t>(i)] = sum;
      }
      // Its Fourier terms in azimuth (midpoint rule over the half circle).
      Spectrum* out = &sun_side_[(k * directions + d) * kModes];
      for (int i = 0; i < kAzimuths; ++i) {
        const AzimuthTerms cosines = azimuth_terms((i + 0.5) * kPi / kAzimuths);
        for (int m = 0; m < kModes; ++m)
          out[m] += sampled[static_cast<size_t>(i)] *
                    static_cast<float>((m == 0 ? 1.0 : 2.0) * cosines[static_cast<size_t>(m)] / kAzimuths);
      }
    }
  });
}

void FogDiffuseField::sun_side_terms(double z, double up, std::array<Spectrum, kModes>& terms) const {
  if (sun_side_.empty()) {
    terms.fill(Spectrum(0.0f));
    return;
  }
  lookup_terms(sun_side_, z, up, terms);
}

double FogDiffuseField::smooth_phase(double cos_angle) const {
  // Σ_l (2l + 1)·χ'_l·P_l(cos Θ)/4π, the Legendre polynomials by their recurrence.
  const double c = std::clamp(cos_angle, -1.0, 1.0);
  double p0 = 1, p1 = c, sum = chi_scaled_[0] + 3 * chi_scaled_[1] * c;
  for (int l = 2; l < static_cast<int>(chi_scaled_.size()); ++l) {
    const double p2 = ((2 * l - 1) * c * p1 - (l - 1) * p0) / l;
    sum += (2 * l + 1) * chi_scaled_[static_cast<size_t>(l)] * p2;
    p0 = p1;
    p1 = p2;
  }
  return sum / (4 * kPi);
}

FogDiffuseField::LevelWeight FogDiffuseField::level_at(double z) const {
  const double zc = std::clamp(z, layer_.bottom_m(), layer_.top_m());
  const double c = layer_.column(zc, 1.0, 0.0, layer_.top_m() - zc);
  size_t k = static_cast<size_t>(std::upper_bound(column_.begin(), column_.end(), c) - column_.begin());
  k = std::clamp<size_t>(k, 1, column_.size() - 1) - 1;
  const double span = column_[k + 1] - column_[k];
  return {k, span > 0 ? static_cast<float>(std::clamp((c - column_[k]) / span, 0.0, 1.0)) : 0.0f};
}

FogDiffuseField::AzimuthTerms FogDiffuseField::azimuth_terms(double relative_azimuth) {
  // cos(mφ) = 2 cos φ·cos((m−1)φ) − cos((m−2)φ): one cosine per call (the sky-light
  // integrals ask for these once per direction).
  AzimuthTerms c{};
  const double c1 = std::cos(relative_azimuth);
  double previous = 1.0, current = c1;
  c[0] = 1.0f;
  c[1] = static_cast<float>(c1);
  for (size_t m = 2; m < c.size(); ++m) {
    const double next = 2 * c1 * current - previous;
    previous = current;
    current = next;
    c[m] = static_cast<float>(next);
  }
  return c;
}

FogDiffuseField::DirectionWeight FogDiffuseField::direction_at(double up) const {
  const size_t directions = direction_.size();
  up = std::clamp(up, direction_.front(), direction_.back());
  size_t d = static_cast<size_t>(std::upper_bound(direction_.begin(), direction_.end(), up) - direction_.begin());
  d = std::clamp<size_t>(d, 1, directions - 1) - 1;
  return {d, static_cast<float>((up - direction_[d]) / (direction_[d + 1] - direction_[d]))};
}

void FogDiffuseField::add_terms(const std::vector<Spectrum>& table, size_t level, DirectionWeight direction,
                                float weight, std::array<Spectrum, kModes>& terms) const {
  const Spectrum* lower = terms_at(table, level, direction.below);
  const Spectrum* upper = lower + kModes;
  const float w_lower = weight * (1 - direction.above), w_upper = weight * direction.above;
  for (int m = 0; m < kModes; ++m) terms[static_cast<size_t>(m)] += lower[m] * w_lower + upper[m] * w_upper;
}

void FogDiffuseField::lookup_terms(const std::vector<Spectrum>& table, double z, double up,
                                   std::array<Spectrum, kModes>& terms) const {
  terms.fill(Spectrum(0.0f));
  if (std::isnan(z) || std::isnan(up)) return;
  const LevelWeight level = level_at(z);
  const DirectionWeight direction = direction_at(up);
  add_terms(table, level.below, direction, 1 - level.above, terms);
  add_terms(table, level.below + 1, direction, level.above, terms);
}

void FogDiffuseField::radiance_terms_at_level(size_t level, double up, std::array<Spectrum, kModes>& terms) const {
  terms.fill(Spectrum(0.0f));
  if (level >= column_.size() || std::isnan(up)) return;
  add_terms(radiance_, level, direction_at(up), 1.0f, terms);
}

Spectrum FogDiffuseField::lookup(const std::vector<Spectrum>& table, double z, double up,
                                 const AzimuthTerms& weights) const {
  Spectrum v(0.0f);
  if (std::isnan(z) || std::isnan(up)) return v;
  const LevelWeight level = level_at(z);
  const DirectionWeight direction = direction_at(up);
  // The four table entries around (z, up), each one level's terms toward one direction.
  auto add = [&](size_t level_index, size_t direction_index, float weight) {
    if (weight == 0.0f) return;
    add_azimuth_weighted(v, terms_at(table, level_index, direction_index), kModes, weights.data(), weight);
  };
  add(level.below, direction.below, (1 - level.above) * (1 - direction.above));
  add(level.below, direction.below + 1, (1 - level.above) * direction.above);
  add(level.below + 1, direction.below, level.above * (1 - direction.above));
  add(level.below + 1, direction.below + 1, level.above * direction.above);
  for (int b = 0; b < kSpectralBins; ++b) v[b] = std::max(v[b], 0.0f);  // a truncated series may dip below 0
  return v;
}

void FogDiffuseField::scattered_terms(double z, double up, std::array<Spectrum, kModes>& terms) const {
  lookup_terms(scattered_, z, up, terms);
}

Spectrum FogDiffuseField::scattered(double z, double up, double relative_azimuth) const {
  return lookup(scattered_, z, up, azimuth_terms(relative_azimuth));
}
Spectrum FogDiffuseField::radiance(double z, double up, double relative_azimuth) const {
  return lookup(radiance_, z, up, azimuth_terms(relative_azimuth));
}
Spectrum FogDiffuseField::radiance_without_sun(double z, double up, double relative_azimuth) const {
  return lookup(without_sun_, z, up, azimuth_terms(relative_azimuth));
}

Spectrum FogDiffuseField::downward_irradiance(double z) const {
  if (std::isnan(z)) return Spectrum(0.0f);
  const LevelWeight level = level_at(z);
  return downward_[level.below] * (1 - level.above) + downward_[level.below + 1] * level.above;
}

}  // namespace skylit
