#include "skylit/atmosphere/direction_grid_phase_quadrature.h"

#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

DirectionGridPhaseQuadrature::DirectionGridPhaseQuadrature(const std::vector<double>& band_mu,
                                                           const std::vector<double>& band_width, int azimuths,
                                                           const std::function<double(double)>& phase)
    : mu_bands_(static_cast<int>(band_mu.size())), azimuths_(azimuths) {
  const int mu_bands = mu_bands_, q_size = azimuths;
  auto mu_of = [&](int k) { return band_mu[static_cast<size_t>(k)]; };
  auto azimuth_of = [&](int q) { return kPi * (q + 0.5) / q_size; };
  analysis_.resize(static_cast<size_t>(q_size * q_size));
  synthesis_.resize(static_cast<size_t>(q_size * q_size));
  for (int m = 0; m < q_size; ++m)
    for (int q = 0; q < q_size; ++q) {
      const double c = std::cos(m * azimuth_of(q));
      analysis_[static_cast<size_t>(m * q_size + q)] = static_cast<float>((m == 0 ? 1.0 : 2.0) / q_size * c);
      synthesis_[static_cast<size_t>(q * q_size + m)] = static_cast<float>(c);
    }
  // K_kk'm in double, times band k''s width in μ (its directions' solid angle, up to
  // the factor 2π/2Q that every direction shares). A row's sum of weights is
  // Σ_k' ½ dω_k' K_kk'0, the same for every azimuth of band k: c_k = 1 / Σ_k' Δμ_k' K_kk'0.
  kernel_.resize(static_cast<size_t>(mu_bands * mu_bands * q_size));
  std::vector<double> k_row(static_cast<size_t>(mu_bands * q_size));
  for (int k = 0; k < mu_bands; ++k) {
    const double mu = mu_of(k), s = std::sqrt(1.0 - mu * mu);
    double row_sum = 0;
    for (int kk = 0; kk < mu_bands; ++kk) {
      const double mu2 = mu_of(kk), s2 = std::sqrt(1.0 - mu2 * mu2);
      for (int m = 0; m < q_size; ++m) {
        double sum = 0;
        for (int j = 0; j < 2 * q_size; ++j) {
          const double delta = kPi * j / q_size;
          sum += phase(mu * mu2 + s * s2 * std::cos(delta)) * std::cos(m * delta);
        }
        k_row[static_cast<size_t>(kk * q_size + m)] = sum * band_width[static_cast<size_t>(kk)];
      }
      row_sum += k_row[static_cast<size_t>(kk * q_size)];
    }
    for (int kk = 0; kk < mu_bands; ++kk)
      for (int m = 0; m < q_size; ++m)
        kernel_[static_cast<size_t>((k * mu_bands + kk) * q_size + m)] =
            static_cast<float>(k_row[static_cast<size_t>(kk * q_size + m)] / row_sum);
  }
}

}  // namespace skylit
