// Element-wise functions of spectra that the atmosphere evaluates millions of times
// while building its tables: written so that the compiler vectorises them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "skylit/spectrum/spectrum.h"

namespace skylit {

// e^x in single precision for x up to 88 (Cephes' expf polynomial, relative error below
// 2e-7 over the range; results under 1e-38 flush to 0). Branch-free so it vectorises
// (libm's expf took a tenth of the scattering orders' build).
inline float exp_fast(float x) {
  x = std::min(std::max(x, -87.0f), 88.0f);
  const float t = x * 1.44269504088896341f;                    // x / ln 2
  const int n = static_cast<int>(t + std::copysign(0.5f, t));  // nearest integer
  const float fn = static_cast<float>(n);
  const float r = x - fn * 0.693359375f + fn * 2.12194440e-4f;  // x − n ln 2 in two parts
  float p = 1.9875691500e-4f;
  p = p * r + 1.3981999507e-3f;
  p = p * r + 8.3334519073e-3f;
  p = p * r + 4.1665795894e-2f;
  p = p * r + 1.6666665459e-1f;
  p = p * r + 5.0000001201e-1f;
  const float y = p * r * r + r + 1.0f;
  const int32_t bits = (n + 127) << 23;  // 2^n
  float scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return y * scale;
}

// e^x for x ≤ 0 (transmittances): positive x is taken as 0.
inline float exp_nonpositive(float x) { return exp_fast(std::min(x, 0.0f)); }

// ∫₀^Δt e^(−σ t) dt = (1 − e^(−σΔt))/σ, given the segment's transmittance e^(−σΔt): the
// weight of a source constant over a segment of length Δt and extinction σ. For thin
// segments (σΔt < 1e-3) from its series, since 1 − e^(−σΔt) loses every digit there
// in single precision.
inline float segment_weight(float extinction, float length, float segment_transmittance) {
  const float x = extinction * length;
  return x < 1e-3f ? length * (1.0f - x * (0.5f - x * (1.0f / 6.0f))) : (1.0f - segment_transmittance) / extinction;
}

// Transmittance e^(−τ) of an optical depth τ ≥ 0 in every bin.
inline Spectrum transmittance_of(const Spectrum& optical_depth) {
  Spectrum out;
  for (int i = 0; i < kSpectralBins; ++i) out[i] = exp_nonpositive(-optical_depth[i]);
  return out;
}

}  // namespace skylit
