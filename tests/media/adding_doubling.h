// An independent solution of radiative transfer in a homogeneous plane-parallel slab,
// for the tests of the path-traced reference: the adding–doubling method (van de Hulst
// 1980, "Multiple Light Scattering", ch. 4; Hansen & Travis 1974, Space Sci. Rev. 16,
// §4.1). Azimuth-independent light only (the m = 0 Fourier term), which is all that a
// uniform sky above a slab gives.
//
// Directions are N Gauss–Legendre cosines μ_i on (0, 1] with weights w_i. A layer's
// reflection and transmission are operators on the radiance at those cosines, the
// quadrature folded in: L_up(μ_i) = Σ_j R_ij L_in(μ_j). A layer of optical thickness
// δ = τ/2^n is solved to first order in δ (single scattering), with its direct
// transmission e^{−δ/μ} exact; n doublings of the symmetric layer,
//   R' = R + T (I − R R)⁻¹ R T,   T' = T (I − R R)⁻¹ T,
// give the slab. With δ ~ 1e-7 the first-order start is exact to ~1e-7.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

namespace skylit::testing {

class AddingDoubling {
 public:
  using Matrix = std::vector<std::vector<double>>;

  // `phase(cos Θ)` normalised to 1 over the sphere (sr⁻¹); ω the single-scattering albedo.
  AddingDoubling(int nodes, double optical_depth, double albedo, const std::function<double(double)>& phase)
      : n_(nodes) {
    gauss_legendre(nodes);
    // The phase function averaged over azimuth between cosines a and b, the incoming
    // direction downward (−b) and the outgoing upward (a) or downward (−a).
    auto mean_over_azimuth = [&](double mu_out, double mu_in) {
      constexpr int kAzimuths = 720;
      const double s = std::sqrt(std::max(0.0, 1 - mu_out * mu_out)) * std::sqrt(std::max(0.0, 1 - mu_in * mu_in));
      double sum = 0;
      for (int k = 0; k < kAzimuths; ++k) sum += phase(mu_out * mu_in + s * std::cos((k + 0.5) * 2 * M_PI / kAzimuths));
      return sum / kAzimuths;
    };
    int doublings = 0;
    double delta = optical_depth;
    while (delta > 1e-7) {
      delta /= 2;
      ++doublings;
    }
    Matrix r(n_, std::vector<double>(n_)), t(n_, std::vector<double>(n_));
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) {
        // Scattered from the incoming beam μ_j over the path δ/μ_i toward μ_i: ω δ/μ_i ·
        // 2π p0 · w_j (the incoming radiance's solid angle is 2π w_j after the azimuth).
        const double factor = albedo * delta / mu_[i] * 2 * M_PI * w_[j];
        r[i][j] = factor * mean_over_azimuth(-mu_[i], mu_[j]);
        t[i][j] = factor * mean_over_azimuth(mu_[i], mu_[j]);
      }
    for (int i = 0; i < n_; ++i) t[i][i] += std::exp(-delta / mu_[i]);
    for (int d = 0; d < doublings; ++d) {
      const Matrix gain = inverse(subtract_from_identity(product(r, r)));
      const Matrix t_gain = product(t, gain);
      const Matrix r2 = add(r, product(product(t_gain, r), t));
      t = product(t_gain, t);
      r = r2;
    }
    reflection_ = r;
    transmission_ = t;
  }

  const std::vector<double>& cosines() const { return mu_; }
  const std::vector<double>& weights() const { return w_; }
  // Radiance leaving the top (upward) and the bottom (downward, direct part included)
  // at cosine μ_i, under a uniform radiance of 1 from above the slab and nothing below.
  double reflected(int i) const { return row_sum(reflection_, i); }
  double transmitted(int i) const { return row_sum(transmission_, i); }

 private:
  void gauss_legendre(int n) {
    // Nodes of P_n on (−1, 1) by Newton's method, mapped to (0, 1).
    for (int i = 0; i < n; ++i) {
      double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
      for (int iter = 0; iter < 100; ++iter) {
        double p0 = 1, p1 = x;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1);
        const double dx = p1 / dp;
        x -= dx;
        if (std::abs(dx) < 1e-15) break;
      }
      mu_.push_back(0.5 * (x + 1));
      w_.push_back(1.0 / ((1 - x * x) * dp * dp));  // 2/((1 − x²)P'²), halved for (0, 1)
    }
  }
  Matrix product(const Matrix& a, const Matrix& b) const {
    Matrix c(n_, std::vector<double>(n_, 0.0));
    for (int i = 0; i < n_; ++i)
      for (int k = 0; k < n_; ++k)
        for (int j = 0; j < n_; ++j) c[i][j] += a[i][k] * b[k][j];
    return c;
  }
  Matrix add(Matrix a, const Matrix& b) const {
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) a[i][j] += b[i][j];
    return a;
  }
  Matrix subtract_from_identity(Matrix a) const {
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) a[i][j] = (i == j ? 1.0 : 0.0) - a[i][j];
    return a;
  }
  Matrix inverse(Matrix a) const {  // Gauss–Jordan with partial pivoting
    Matrix inv(n_, std::vector<double>(n_, 0.0));
    for (int i = 0; i < n_; ++i) inv[i][i] = 1;
    for (int c = 0; c < n_; ++c) {
      int pivot = c;
      for (int r = c + 1; r < n_; ++r)
        if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
      std::swap(a[c], a[pivot]);
      std::swap(inv[c], inv[pivot]);
      const double d = a[c][c];
      for (int j = 0; j < n_; ++j) {
        a[c][j] /= d;
        inv[c][j] /= d;
      }
      for (int r = 0; r < n_; ++r) {
        if (r == c) continue;
        const double f = a[r][c];
        for (int j = 0; j < n_; ++j) {
          a[r][j] -= f * a[c][j];
          inv[r][j] -= f * inv[c][j];
        }
      }
    }
    return inv;
  }
  static double row_sum(const Matrix& m, int i) {
    double s = 0;
    for (double v : m[i]) s += v;
    return s;
  }

  int n_;
  std::vector<double> mu_, w_;
  Matrix reflection_, transmission_;
};

}  // namespace skylit::testing
