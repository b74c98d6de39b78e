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
  Spectrum transmittance(1.0f), in_scattered(0.0f);
  for (int k = 0; k < kSpectralBins; ++k) {
    const float through = near.transmittance[k];
    if (through <= 0.0f) continue;
    transmittance[k] = std::clamp(whole.transmittance[k] / through, 0.0f, 1.0f);
    in_scattered[k] = std::max(0.0f, (whole.in_scattered[k] - near.in_scattered[k]) / through);
  }
  return {Transmittance(transmittance), Radiance(in_scattered)};
}

MediumStretch mixed(const MediumStretch& a, const MediumStretch& b) {
  Spectrum in_scattered;
  for (int k = 0; k < kSpectralBins; ++k) {
    const double depth_a = optical_depth(a.transmittance[k]), depth_b = optical_depth(b.transmittance[k]);
    const double both = mean_transmittance(depth_a + depth_b);
    in_scattered[k] = static_cast<float>(a.in_scattered[k] * (both / mean_transmittance(depth_a)) +
                                         b.in_scattered[k] * (both / mean_transmittance(depth_b)));
  }
  return {a.transmittance * b.transmittance, Radiance(in_scattered)};
}

}  // namespace skylit
