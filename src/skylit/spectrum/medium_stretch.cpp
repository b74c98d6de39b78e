#include "skylit/spectrum/medium_stretch.h"

#include <algorithm>
#include <cmath>

namespace skylit {

namespace {

// An optical depth large enough that nothing gets through, finite so that the ratios
// below stay defined where a transmittance is 0.
constexpr double kOpaqueDepth = 1e6;

double optical_depth(float transmittance) {
  return transmittance > 0.0f ? std::min(kOpaqueDepth, -std::log(static_cast<double>(transmittance))) : kOpaqueDepth;
}

// g(τ) = (1 − e^−τ)/τ: the mean of e^−t over t ∈ [0, τ].
double mean_transmittance(double depth) { return depth < 1e-8 ? 1.0 - 0.5 * depth : -std::expm1(-depth) / depth; }

}  // namespace

MediumStretch remainder_after(const MediumStretch& near, const MediumStretch& whole) {
  // Where nothing gets through the near stretch, nothing of the rest is known: 1 and 0.
  // Written without a branch so that the bins go through the divisions together (the
  // loop with one was 3 % of a fog frame).
  Spectrum transmittance, in_scattered;
  for (int k = 0; k < kSpectralBins; ++k) {
    const float through = near.transmittance[k];
    const bool passes = !(through <= 0.0f);
    const float divisor = passes ? through : 1.0f;
    const float rest = std::clamp(whole.transmittance[k] / divisor, 0.0f, 1.0f);
    const float added = std::max(0.0f, (whole.in_scattered[k] - near.in_scattered[k]) / divisor);
    transmittance[k] = passes ? rest : 1.0f;
    in_scattered[k] = passes ? added : 0.0f;
  }
  return {Transmittance(transmittance), Radiance(in_scattered)};
}

MediumStretch mixed(const MediumStretch& a, const MediumStretch& b) {
  // The two dimming factors change smoothly with wavelength (optical depths of the air
  // and of fog or haze follow smooth laws in λ), so they are computed at every
  // kFactorStride-th bin and the last, and interpolated linearly between: a logarithm
  // and three exponentials per bin made this a third of a fog frame's time.
  constexpr int kFactorStride = 13;  // bins 0, 13, 26, 39: every 130 nm
  auto factors_at = [&](int k, double& for_a, double& for_b) {
    const double depth_a = optical_depth(a.transmittance[k]), depth_b = optical_depth(b.transmittance[k]);
    const double both = mean_transmittance(depth_a + depth_b);
    for_a = both / mean_transmittance(depth_a);
    for_b = both / mean_transmittance(depth_b);
  };
  Spectrum in_scattered;
  int k0 = 0;
  double a0, b0;
  factors_at(0, a0, b0);
  while (k0 < kSpectralBins - 1) {
    const int k1 = std::min(k0 + kFactorStride, kSpectralBins - 1);
    double a1, b1;
    factors_at(k1, a1, b1);
    for (int k = k0; k <= k1; ++k) {
      const double t = static_cast<double>(k - k0) / (k1 - k0);
      in_scattered[k] =
          static_cast<float>(a.in_scattered[k] * (a0 + (a1 - a0) * t) + b.in_scattered[k] * (b0 + (b1 - b0) * t));
    }
    k0 = k1;
    a0 = a1;
    b0 = b1;
  }
  return {a.transmittance * b.transmittance, Radiance(in_scattered)};
}

}  // namespace skylit
