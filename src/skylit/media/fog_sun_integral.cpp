// The closed form of the sunlight that fog scatters toward the viewer (Eqs. 11–12 with
// the Appendix's Eqs. 17–28), for a layer with a bottom and a top.
//
// Derivation. Let [a, b] be the part of [s1, s2] inside the layer (outside it τ = 0, so
// it adds nothing). For s in [a, b] write D(s) = τ(s) = σ·ρ(z(s)) (Eq. 9) and
//     t(s)  = t(a) + ∫_a^s D ds                                  (Eq. 10),
//     t'(s) = ∫ from z(s) up to the top along the sun = σ·ρ0·h0/z_L·(e^(−z(s)/h0) − e^(−z_t/h0))
// (Eq. 19 with the top's term). Along the ray dD/ds = −(z_v/h0)·D, so
//     dt'/ds = (σρ0/z_L)·(−z_v)·e^(−z(s)/h0) = −(z_v/z_L)·D(s),
// and with X(s) = t(s) − t(a) + t'(s):
//     dX/ds = D(s)·(1 − z_v/z_L) = ε·D(s).
// The integrand of Eq. 21 is D·e^(−t(a))·e^(−X), i.e. −e^(−t(a))/ε · d(e^(−X))/ds, hence
//     I/(E·F) = e^(−t(a))·(e^(−X(a)) − e^(−X(b)))/ε,      X(b) − X(a) = ε·T, T = ∫_a^b D ds.
// Nothing here divides by h0 or z_v: the same expression is Eq. 23 when z_v = 0 (ε = 1),
// Eq. 25 when z_v = z_L (ε → 0: the limit is e^(−t(a)−X(a))·T), Eq. 28 otherwise, and
// the homogeneous layer when |h0| → ∞. (In the paper's variables u = e^(−z_v s/h0) of
// Eq. 26, D, t and t' are all affine in u, so the integrand is e^(c0 + c1·u)·du: the same
// result. Eq. 28 as printed lacks a minus sign — its bracket must run from u(s2) down to
// u(s1), as those of Eqs. 23 and 25 do — see docs/fog.md.)
//
// Stable evaluation. Factor out the larger of e^(−X(a)), e^(−X(b)) — X(a) when ε ≥ 0,
// X(b) = X(a) + ε·T when ε < 0 (the view steeper than the sun) — leaving
//     (1 − e^(−|ε|·T))/|ε| = T·g(|ε|·T),   g(y) = (1 − e^(−y))/y ∈ (0, 1],
// from expm1, or its series for tiny |ε|·T. Every factor is then ≤ 1 or equals T: no
// cancellation anywhere, so the result is continuous through ε = 0, z_v = 0 and
// h0 → ±∞ to rounding error.
#include "skylit/media/fog_sun_integral.h"

#include <algorithm>
#include <cmath>

namespace skylit {
namespace {

constexpr double kHuge = 1e300;

}  // namespace

FogSunSegment fog_sun_segment(const FogLayer& layer, double z_p, double z_v, double z_sun, double s1, double s2) {
  FogSunSegment out;
  if (!(z_sun > 0.0)) return out;  // no direct sunlight with the sun at or below the horizon
  const RaySpan span = layer.clip(z_p, z_v, std::max(s1, 0.0), s2);
  if (span.empty()) return out;
  const double length = span.hi - span.lo, rise = z_v * length;
  const double z_a = std::clamp(z_p + z_v * span.lo, layer.bottom_m(), layer.top_m());
  const double z_b = std::clamp(z_a + rise, layer.bottom_m(), layer.top_m());
  out.lit = true;
  out.viewer_to_start = layer.column(z_p, z_v, 0.0, span.lo);
  out.segment = layer.piece_column(z_a, rise, length);
  out.sun_from_start = std::min(layer.sun_column(z_a, z_sun), kOpaqueColumnM);
  out.sun_from_end = std::min(layer.sun_column(z_b, z_sun), kOpaqueColumnM);
  // (z_L − z_v)/z_L rather than 1 − z_v/z_L: the difference of nearly equal cosines is
  // exact, so ε keeps its relative precision as z_v → z_L.
  out.slope_mismatch = std::clamp((z_sun - z_v) / z_sun, -kHuge, kHuge);
  return out;
}

double fog_sun_weight(const FogSunSegment& s, double sigma) {
  if (!s.lit) return 0.0;
  sigma = std::clamp(sigma, 0.0, kHuge);
  const auto depth = [sigma](double column) { return std::min(sigma * column, kOpaqueColumnM); };
  const double t_a = depth(s.viewer_to_start);  // t(a)
  const double big_t = depth(s.segment);        // T
  const double eps = s.slope_mismatch;
  // X at the end where e^(−X) is larger: X(a) = t'(a), or X(b) = T + t'(b).
  const double x_min = eps >= 0.0 ? depth(s.sun_from_start) : big_t + depth(s.sun_from_end);
  const double e = std::abs(eps), y = e * big_t;
  const double t_g = y < 1e-5 ? big_t * (1.0 - y * (0.5 - y / 6.0)) : -std::expm1(-y) / e;  // T·g(|ε|T)
  return std::exp(-(t_a + x_min)) * t_g;
}

double fog_sun_weight(const FogLayer& layer, double z_p, double z_v, double z_sun, double s1, double s2,
                      double wavelength_nm) {
  return fog_sun_weight(fog_sun_segment(layer, z_p, z_v, z_sun, s1, s2),
                        layer.unit_density_extinction_per_m(wavelength_nm));
}

Spectrum fog_sun_inscatter(const FogLayer& layer, const Vec3& viewpoint, const Vec3& view_dir, const Vec3& to_sun,
                           double s1, double s2, const Spectrum& sun_irradiance, double sun_depth_scale) {
  Spectrum out;
  // With k < 1 the forward spike's light stays in the beam both before and after the
  // one scattering by F (δ-M's "TMS" single scattering): the optical depths toward the
  // sun and back to the viewpoint are both scaled by k, i.e. σ becomes k·σ in the closed
  // form, and the scattering coefficient k·σ in it is divided back by k.
  const double k = std::clamp(sun_depth_scale, 1e-6, 1.0);
  const FogSunSegment segment = fog_sun_segment(layer, viewpoint.z, view_dir.z, to_sun.z, s1, s2);
  if (!segment.lit) return out;
  // F(θ) is constant along the segment for parallel light (§5.1), so it factors out.
  const double scale = layer.single_scattering_albedo() * layer.phase(dot(view_dir, to_sun));
  const auto& sigma = layer.unit_density_extinction_bins();
  double last_sigma = -1.0, weight = 0.0;  // with b = 0 (the default) every bin has the same σ
  for (int i = 0; i < kSpectralBins; ++i) {
    const double s = sigma[static_cast<size_t>(i)];
    if (s != last_sigma) weight = fog_sun_weight(segment, k * (last_sigma = s)) / k;
    out[i] = static_cast<float>(scale * sun_irradiance[i] * weight);
  }
  return out;
}

}  // namespace skylit
