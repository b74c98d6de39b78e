// ∫ P(ω·ω') L(ω') dω' over the scattering-orders table's grid of directions
// (atmosphere/scattering_orders_table.h), for a field L that is mirror-symmetric about
// the sun's vertical: K bands of μ (of any widths Δμ_k), in each Q azimuths φ_q =
// π(q + ½)/Q in [0, π], each standing for itself and its mirror image −φ_q.
//
// The quadrature is the plain sum S(d) = Σ_e w(d, e) L(e) / Σ_e w(d, e) with w(d, e) =
// ½ [P(ω_d·ω_e) + P(ω_d·ω_e')] dω_e, dω_e ∝ Δμ_e (ω_e' the mirror image; each row
// normalised so that it conserves energy exactly, the aerosol's forward peak being
// coarse on this grid). It is taken by azimuthal Fourier modes rather than as a matrix:
// on the full circle the 2Q azimuths are equally spaced, so the sum over azimuths is a
// circular convolution with a kernel even in the azimuth difference, and a
// mirror-symmetric field is a sum of cos(mφ), m < Q, on which the convolution acts as
// one factor per mode:
//   L(k, φ) = Σ_m a_km cos(mφ),
//   S(k, φ) = Σ_m cos(mφ) Σ_k' c_k Δμ_k' K_kk'm a_k'm,
//   K_kk'm = Σ_{j < 2Q} P(μ_k μ_k' + √((1 − μ_k²)(1 − μ_k'²)) cos Δ_j) cos(mΔ_j), Δ_j = πj/Q,
// with c_k the row's normalisation (the same for every azimuth of band k, by the grid's
// symmetry). The same sum as the matrix, in K·Q·(K + 2Q) products per channel and
// phase function instead of (K·Q)²: a quarter at 16 × 8 (the modes of L are shared by
// both phase functions).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace skylit {

class DirectionGridPhaseQuadrature {
 public:
  // The bands of μ by their directions' μ and their widths in μ (any spacing: each
  // direction weighs its band's solid angle); `phase`: the phase function of the
  // scattering angle's cosine, sr⁻¹ (its normalisation cancels).
  DirectionGridPhaseQuadrature(const std::vector<double>& band_mu, const std::vector<double>& band_width, int azimuths,
                               const std::function<double(double)>& phase);

  // The field's modes a_km ([k·Q + m]) from its values at the grid's directions
  // ([k·Q + q]); the same for every phase function.
  template <size_t N>
  void modes_of(const std::array<float, N>* values, std::array<float, N>* modes) const;
  // S at every direction of the grid ([k·Q + p]) from the field's modes.
  template <size_t N>
  void integrate(const std::array<float, N>* modes, std::array<float, N>* out) const;

 private:
  int mu_bands_, azimuths_;
  std::vector<float> analysis_;   // [m·Q + q]: (m = 0 ? 1 : 2)/Q · cos(mφ_q)
  std::vector<float> synthesis_;  // [p·Q + m]: cos(mφ_p)
  std::vector<float> kernel_;     // [(k·K + k')·Q + m]: c_k Δμ_k' K_kk'm
};

template <size_t N>
void DirectionGridPhaseQuadrature::modes_of(const std::array<float, N>* values, std::array<float, N>* modes) const {
  const int q_size = azimuths_;
  for (int k = 0; k < mu_bands_; ++k)
    for (int m = 0; m < q_size; ++m) {
      std::array<float, N> sum{};
      for (int q = 0; q < q_size; ++q) {
        const float c = analysis_[static_cast<size_t>(m * q_size + q)];
        const std::array<float, N>& v = values[k * q_size + q];
        for (size_t i = 0; i < N; ++i) sum[i] += c * v[i];
      }
      modes[k * q_size + m] = sum;
    }
}

template <size_t N>
void DirectionGridPhaseQuadrature::integrate(const std::array<float, N>* modes, std::array<float, N>* out) const {
  const int q_size = azimuths_;
  thread_local std::vector<std::array<float, N>> per_mode;
  per_mode.resize(static_cast<size_t>(q_size));
  for (int k = 0; k < mu_bands_; ++k) {
    for (auto& t : per_mode) t.fill(0.0f);
    for (int kk = 0; kk < mu_bands_; ++kk) {
      const float* row = &kernel_[static_cast<size_t>((k * mu_bands_ + kk) * q_size)];
      for (int m = 0; m < q_size; ++m) {
        const std::array<float, N>& a = modes[kk * q_size + m];
        std::array<float, N>& t = per_mode[static_cast<size_t>(m)];
        for (size_t i = 0; i < N; ++i) t[i] += row[m] * a[i];
      }
    }
    for (int p = 0; p < q_size; ++p) {
      std::array<float, N> sum{};
      for (int m = 0; m < q_size; ++m) {
        const float c = synthesis_[static_cast<size_t>(p * q_size + m)];
        for (size_t i = 0; i < N; ++i) sum[i] += c * per_mode[static_cast<size_t>(m)][i];
      }
      out[k * q_size + p] = sum;
    }
  }
}

}  // namespace skylit
