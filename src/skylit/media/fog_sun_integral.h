// Sunlight scattered toward the viewer by a fog layer along a lit segment [s1, s2] of a
// view ray, in closed form: Eq. 11 with the sun's light function of Eq. 12, integrated
// as in the paper's Appendix (Eqs. 17–28) but for a layer with a bottom and a top:
//     I = ω·F(θ)·E_sun·∫_{s1}^{s2} τ(s)·e^(−t'(s))·e^(−t(s)) ds,
// t(s) the fog's optical depth from the viewpoint to s, t'(s) that from s toward the
// sun, τ(s) the extinction (Eq. 9), ω the single-scattering albedo. The derivation — one
// formula for all of the paper's cases z_v = 0, z_v = z_L and the general one — is in
// the .cpp and in docs/fog.md.
//
// The view ray is z(s) = z_p + z_v·s (s in metres from the viewpoint, z_v the view
// direction's vertical cosine); the sun's direction has vertical cosine z_L (the
// paper's z_Lk). Segments come from the caller (shadow volumes later); the fog between
// the viewpoint and s1 still attenuates.
#pragma once

#include "skylit/core/vec3.h"
#include "skylit/media/fog_layer.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// The wavelength-free part of the closed form: columns N = ∫ρ ds (m) of the segment's
// part inside the layer, [a, b] = [s1, s2] ∩ layer.
struct FogSunSegment {
  bool lit = false;              // false: no part in the layer, or the sun at/below the horizon
  double viewer_to_start = 0.0;  // from the viewpoint to a (t(a) = σ·this)
  double segment = 0.0;          // from a to b
  double sun_from_start = 0.0;   // the column from z(a) toward the sun (t'(a) = σ·this)
  double sun_from_end = 0.0;     // the same from z(b)
  double slope_mismatch = 0.0;   // ε = 1 − z_v/z_L: d(t + t')/ds = ε·τ(s)
};

FogSunSegment fog_sun_segment(const FogLayer& layer, double z_p, double z_v, double z_sun, double s1, double s2);

// ∫ σρ(s)·e^(−t'(s))·e^(−t(s)) ds over the segment for an extinction at unit density σ
// (m⁻¹): a pure number in [0, 1]. Finite and ≥ 0 for any finite input.
double fog_sun_weight(const FogSunSegment& segment, double unit_density_extinction_per_m);

// The same at one wavelength (nm), from the geometry: the scalar form for tests.
double fog_sun_weight(const FogLayer& layer, double z_p, double z_v, double z_sun, double s1, double s2,
                      double wavelength_nm);

// Radiance (W m⁻² sr⁻¹ nm⁻¹) in each bin scattered toward the viewpoint from the segment
// [s1, s2] of the ray from `viewpoint` along the unit `view_dir`, for sunlight from the
// unit direction `to_sun` whose irradiance on a plane facing the sun, without fog, is
// `sun_irradiance` (W m⁻² nm⁻¹): ω·F(θ)·E·weight, cos θ = view_dir·to_sun.
// With `sun_depth_scale` k < 1 (δ-M, media/fog_diffuse_field.h) the optical depths toward
// the sun and back to the viewpoint are both scaled by k: the forward spike's light stays
// in the beam before and after the one scattering by F (the "TMS" single scattering).
Spectrum fog_sun_inscatter(const FogLayer& layer, const Vec3& viewpoint, const Vec3& view_dir, const Vec3& to_sun,
                           double s1, double s2, const Spectrum& sun_irradiance, double sun_depth_scale = 1.0);

}  // namespace skylit
