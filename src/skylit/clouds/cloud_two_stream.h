// Multiple scattering inside a cloud (§6's component iii) from radiative transfer: the
// delta-Eddington two-stream solution of a plane-parallel, non-absorbing slab (Joseph,
// Wiscombe & Weinman 1976, "The delta-Eddington approximation for radiative flux
// transfer", J. Atmos. Sci. 33:2452–2459), the classic choice for the strongly
// forward-peaked phase function of cloud droplets.
//
// Delta scaling. A fraction f = g² of the scattering goes into a forward spike that is
// treated as no scattering at all; the rest has mean cosine g' = (g − f)/(1 − f) and the
// optical depth shrinks to τ' = (1 − f)τ. For the droplets (g = 0.879): f = 0.77,
// g' = 0.47, so a cloud of optical depth 20 is a scaled slab of 4.5.
//
// Eddington. The diffuse radiance is I(τ', μ) = I0(τ') + μ·I1(τ'), μ the cosine of the
// direction of travel with the downward vertical. With ω = 1 and the phase function
// 1 + 3g' cos Θ (the two moments the Eddington field sees), the moment equations
//   dI1/dτ' = (3/4π) E0 e^{−τ'/μ0},   dI0/dτ' = −(1 − g') I1 + (3/4π) g' μ0 E0 e^{−τ'/μ0}
// (E0: the direct beam's irradiance normal to it, μ0 the sun's cosine) are solved in
// closed form with Marshak's boundary conditions: the diffuse flux π(I0 ± 2/3 I1) going
// into the slab at its top and bottom is what the sky and the ground send there. The
// light a diffuse field scatters toward a direction of downward cosine μ is then
// I0 + g' μ I1 (orders two and up; the first order is the caller's, with the true phase
// function). The albedo it implies, R = [γ1 τ' + (1/2 − 3μ0/4)(1 − e^{−τ'/μ0})]/(1 + γ1 τ')
// with γ1 = 3(1 − g')/4, is Meador & Weaver's (1980, J. Atmos. Sci. 37:630–643)
// conservative two-stream result (tests/clouds/cloud_two_stream_test.cpp checks both).
#pragma once

namespace skylit {

// Similarity (delta) scaling of a phase function of mean cosine g.
struct DeltaScaling {
  double forward_fraction;  // f = g²: the forward spike taken as unscattered
  double asymmetry;         // g' = (g − f)/(1 − f)
  explicit DeltaScaling(double g);
  double scaled_depth(double optical_depth) const { return (1 - forward_fraction) * optical_depth; }
};

// The Eddington diffuse radiance I0 + μ I1 at one depth (W m⁻² sr⁻¹ per unit of the source's
// irradiance).
struct EddingtonField {
  double mean = 0;  // I0
  double flux = 0;  // I1 (3/4π times the net downward flux)
  // The light this field scatters toward a direction of travel with downward cosine mu,
  // per unit of scaled optical depth: I0 + g' μ I1.
  double scattered(double g_scaled, double mu) const { return mean + g_scaled * mu * flux; }
};

// A conservative slab of scaled optical depth `depth` and scaled asymmetry `g`; `tau` is
// the scaled depth below its top (clamped to [0, depth]).
//
// The field lit by the sun (unit irradiance normal to the beam, cosine mu0 > 0) on the top.
EddingtonField eddington_sun_field(double depth, double g, double mu0, double tau);
// The field lit by a unit diffuse irradiance on the top face (from_top) or the bottom face.
EddingtonField eddington_diffuse_field(double depth, double g, double tau, bool from_top);
// The slab's albedo for the sun: the diffuse flux leaving its top over μ0 E0.
double eddington_sun_albedo(double depth, double g, double mu0);

}  // namespace skylit
