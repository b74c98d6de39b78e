// The fog's diffuse radiance field by δ-M discrete ordinates (fog_diffuse_field.h).
//
// Depth. τ' = (1 − ωf)·σ·c, c the fog's column from the top (m; FogLayer::column), so
// every bin shares the levels, placed in c: thin near both faces (where the sky's and the
// ground's light enters and the field changes over a fraction of an optical depth) and
// growing by a tenth of the distance to the nearer face inside, where the field is
// diffuse and smooth.
//
// Characteristics. Along a stream of cosine μ across a layer of scaled depth Δ, with the
// source S (per unit scaled extinction) linear in depth between its values S_in at the
// level where the stream enters and S_out where it leaves, x = Δ/μ:
//     L_out = e^{−x}·L_in + (g(x) − e^{−x})·S_in + (1 − g(x))·S_out,   g(x) = (1 − e^{−x})/x,
// exact for a linear source, with weights ≥ 0 for any x (no oscillation in thick layers).
// S = ω'·Σ_t 2π w_t p'(u, u_t)·L_t + ω'·p'(u, −μ0)·E0·e^{−τ'/μ0}, p' the azimuthal mean
// of the δ-M phase function, Σ_l (2l + 1)/4π·χ'_l·P_l(u)·P_l(u').
#include "skylit/media/fog_diffuse_field.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "skylit/core/angles.h"
#include "skylit/core/banded_matrix.h"

namespace skylit {
namespace {

constexpr int kN = FogDiffuseField::kStreams;
constexpr int kStreamsAll = 2 * kN;

// Gauss–Legendre nodes and weights on [0, 1] (weights sum to 1).
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
  std::vector<double> chi_scaled(kStreamsAll, 0.0);
  for (int l = 0; l < kept; ++l) chi_scaled[static_cast<size_t>(l)] = (chi[static_cast<size_t>(l)] - f_) / (1 - f_);
  auto phase_mean = [&](const std::vector<double>& pa, const std::vector<double>& pb) {
    double sum = 0;
    for (int l = 0; l < kStreamsAll; ++l)
      sum += (2 * l + 1) / (4 * kPi) * chi_scaled[static_cast<size_t>(l)] * pa[static_cast<size_t>(l)] *
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
  std::vector<std::vector<double>> p_node;
  p_node.reserve(u.size());
  for (double us : u) p_node.push_back(legendre(us, kStreamsAll));
  const double mu0 = lighting.sun_cosine;
  const bool sun = mu0 > 0 && !lighting.sun_irradiance.is_black();
  const std::vector<double> p_sun = legendre(-std::max(mu0, 0.0), kStreamsAll);
  // The coupling ω'·2π·w_t·p'(u_s, u_t) and the sun's ω'·p'(u_s, −μ0).
  std::vector<double> coupling(kStreamsAll * kStreamsAll), sun_coupling(kStreamsAll);
  for (int s = 0; s < kStreamsAll; ++s) {
    for (int t = 0; t < kStreamsAll; ++t)
      coupling[static_cast<size_t>(s * kStreamsAll + t)] =
          omega_scaled * 2 * kPi * w[static_cast<size_t>(t)] *
          phase_mean(p_node[static_cast<size_t>(s)], p_node[static_cast<size_t>(t)]);
    sun_coupling[static_cast<size_t>(s)] = sun ? omega_scaled * phase_mean(p_node[static_cast<size_t>(s)], p_sun) : 0.0;
  }

  // Output directions: upward cosines ±((m + 1)/M)², crowding toward the horizon.
  constexpr int kM = kDirectionsPerHemisphere;
  for (int m = kM - 1; m >= 0; --m) direction_.push_back(-std::pow((m + 1.0) / kM, 2));
  for (int m = 0; m < kM; ++m) direction_.push_back(std::pow((m + 1.0) / kM, 2));
  const size_t directions = direction_.size();
  std::vector<std::vector<double>> p_out;
  for (double uo : direction_) p_out.push_back(legendre(uo, kStreamsAll));

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
      double step = std::min({first + 0.1 * nearer, widest, depth / 16});
      if (depth - at < 1.3 * step) step = depth - at;
      at += step;
      column_.push_back(at >= depth ? total : at / scale);
    }
  } else {
    column_.push_back(std::max(total, 0.0));
  }
  const int levels = static_cast<int>(column_.size()), layers = levels - 1;

  // The sky at the streams' and the output directions' cosines.
  std::vector<Spectrum> sky_node(kN), sky_out(directions);
  for (int s = 0; s < kN; ++s) sky_node[static_cast<size_t>(s)] = lighting.sky(mu[static_cast<size_t>(s)]);
  for (size_t m = 0; m < directions; ++m)
    if (direction_[m] < 0) sky_out[m] = lighting.sky(-direction_[m]);

  scattered_.assign(static_cast<size_t>(levels) * directions, Spectrum(0.0f));
  radiance_.assign(scattered_.size(), Spectrum(0.0f));
  downward_.assign(static_cast<size_t>(levels), Spectrum(0.0f));
  const double ground = std::clamp(lighting.ground_albedo, 0.0, 1.0) / kPi;

  // Bins of equal σ share one system (all of them for grey fog).
  std::map<double, std::vector<int>> groups;
  for (int b = 0; b < kSpectralBins; ++b) groups[sigma[static_cast<size_t>(b)]].push_back(b);
  const int n = kStreamsAll * levels;
  for (const auto& [sigma_group, bins] : groups) {
    const double per_column = depth_scale * sigma_group;
    std::vector<double> tau(static_cast<size_t>(levels));
    for (int k = 0; k < levels; ++k)
      tau[static_cast<size_t>(k)] = std::min(per_column * column_[static_cast<size_t>(k)], 1e12);
    auto weights = [&](int k, double mu_s) {
      return step_weights(tau[static_cast<size_t>(k + 1)] - tau[static_cast<size_t>(k)], mu_s);
    };
    BandedMatrix a(n, 3 * kN - 1, 3 * kN - 1);
    auto column_of = [](int level, int stream) { return kStreamsAll * level + stream; };
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
    for (int s = kN; s < kStreamsAll; ++s) {  // the ground reflects the downward flux
      const int row = kN + kStreamsAll * layers + (s - kN);
      a.at(row, column_of(layers, s)) += 1.0;
      for (int t = 0; t < kN; ++t)
        a.at(row, column_of(layers, t)) -= ground * 2 * kPi * w[static_cast<size_t>(t)] * mu[static_cast<size_t>(t)];
    }
    if (!a.factorise()) continue;  // cannot happen for ω' ≤ 1; the field stays 0

    for (int b : bins) {
      const double e0 = sun ? lighting.sun_irradiance[b] : 0.0;
      auto beam = [&](int k) { return sun ? e0 * std::exp(-tau[static_cast<size_t>(k)] / mu0) : 0.0; };
      std::vector<double> rhs(static_cast<size_t>(n), 0.0);
      for (int s = 0; s < kN; ++s) rhs[static_cast<size_t>(s)] = sky_node[static_cast<size_t>(s)][b];
      for (int k = 0; k < layers; ++k)
        for (int s = 0; s < kStreamsAll; ++s) {
          const StepWeights sw = weights(k, mu[static_cast<size_t>(s)]);
          const bool down = s < kN;
          const int in = down ? k : k + 1, out = down ? k + 1 : k;
          rhs[static_cast<size_t>(kN + kStreamsAll * k + s)] =
              sun_coupling[static_cast<size_t>(s)] * (sw.entry * beam(in) + sw.exit * beam(out));
        }
      const double ground_direct = sun ? ground * mu0 * beam(layers) : 0.0;
      for (int s = kN; s < kStreamsAll; ++s)
        rhs[static_cast<size_t>(kN + kStreamsAll * layers + (s - kN))] = ground_direct;
      a.solve(rhs);
      auto node = [&](int k, int t) { return std::max(0.0, rhs[static_cast<size_t>(column_of(k, t))]); };

      for (int k = 0; k < levels; ++k) {
        double flux = 0;
        for (int t = 0; t < kN; ++t)
          flux += 2 * kPi * w[static_cast<size_t>(t)] * mu[static_cast<size_t>(t)] * node(k, t);
        downward_[static_cast<size_t>(k)][b] = static_cast<float>(flux);
      }
      const double ground_up = ground * (downward_[static_cast<size_t>(layers)][b] + mu0 * beam(layers));

      // Each output direction: its source at every level, its radiance by the formal
      // solution, and the light scattered toward it.
      std::vector<double> source(static_cast<size_t>(levels)), body(static_cast<size_t>(levels));
      for (size_t m = 0; m < directions; ++m) {
        const double uo = direction_[m], mu_o = std::abs(uo);
        const double sun_c = sun ? omega_scaled * phase_mean(p_out[m], p_sun) : 0.0;
        for (int k = 0; k < levels; ++k) {
          double integral = 0;  // ∫ p' L over the streams
          for (int t = 0; t < kStreamsAll; ++t)
            integral +=
                2 * kPi * w[static_cast<size_t>(t)] * phase_mean(p_out[m], p_node[static_cast<size_t>(t)]) * node(k, t);
          body[static_cast<size_t>(k)] = integral;
          source[static_cast<size_t>(k)] = omega_scaled * integral + sun_c * beam(k);
        }
        std::vector<double> l(static_cast<size_t>(levels));
        if (uo < 0) {
          l[0] = sky_out[m][b];
          for (int k = 0; k < layers; ++k) {
            const StepWeights sw = weights(k, mu_o);
            l[static_cast<size_t>(k + 1)] = sw.through * l[static_cast<size_t>(k)] +
                                            sw.entry * source[static_cast<size_t>(k)] +
                                            sw.exit * source[static_cast<size_t>(k + 1)];
          }
        } else {
          l[static_cast<size_t>(layers)] = ground_up;
          for (int k = layers - 1; k >= 0; --k) {
            const StepWeights sw = weights(k, mu_o);
            l[static_cast<size_t>(k)] = sw.through * l[static_cast<size_t>(k + 1)] +
                                        sw.entry * source[static_cast<size_t>(k + 1)] +
                                        sw.exit * source[static_cast<size_t>(k)];
          }
        }
        for (int k = 0; k < levels; ++k) {
          const size_t at = static_cast<size_t>(k) * directions + m;
          const double radiance = std::max(0.0, l[static_cast<size_t>(k)]);
          const double scattered = std::max(0.0, f_ * radiance + (1 - f_) * body[static_cast<size_t>(k)]);
          radiance_[at][b] = static_cast<float>(radiance);
          scattered_[at][b] = static_cast<float>(scattered);
          largest_[static_cast<size_t>(b)] = std::max(largest_[static_cast<size_t>(b)], scattered);
        }
      }
    }
  }
}

FogDiffuseField::LevelWeight FogDiffuseField::level_at(double z) const {
  const double zc = std::clamp(z, layer_.bottom_m(), layer_.top_m());
  const double c = layer_.column(zc, 1.0, 0.0, layer_.top_m() - zc);
  size_t k = static_cast<size_t>(std::upper_bound(column_.begin(), column_.end(), c) - column_.begin());
  k = std::clamp<size_t>(k, 1, column_.size() - 1) - 1;
  const double span = column_[k + 1] - column_[k];
  return {k, span > 0 ? static_cast<float>(std::clamp((c - column_[k]) / span, 0.0, 1.0)) : 0.0f};
}

Spectrum FogDiffuseField::lookup(const std::vector<Spectrum>& table, double z, double up) const {
  if (std::isnan(z) || std::isnan(up)) return Spectrum(0.0f);
  const LevelWeight level = level_at(z);
  const size_t k = level.below, directions = direction_.size();
  up = std::clamp(up, direction_.front(), direction_.back());
  size_t m = static_cast<size_t>(std::upper_bound(direction_.begin(), direction_.end(), up) - direction_.begin());
  m = std::clamp<size_t>(m, 1, directions - 1) - 1;
  const float fm = static_cast<float>((up - direction_[m]) / (direction_[m + 1] - direction_[m]));
  auto at = [&](size_t kk, size_t mm) { return table[kk * directions + mm]; };
  return (at(k, m) * (1 - fm) + at(k, m + 1) * fm) * (1 - level.above) +
         (at(k + 1, m) * (1 - fm) + at(k + 1, m + 1) * fm) * level.above;
}

Spectrum FogDiffuseField::scattered(double z, double up) const { return lookup(scattered_, z, up); }
Spectrum FogDiffuseField::radiance(double z, double up) const { return lookup(radiance_, z, up); }

Spectrum FogDiffuseField::downward_irradiance(double z) const {
  if (std::isnan(z)) return Spectrum(0.0f);
  const LevelWeight level = level_at(z);
  return downward_[level.below] * (1 - level.above) + downward_[level.below + 1] * level.above;
}

}  // namespace skylit
