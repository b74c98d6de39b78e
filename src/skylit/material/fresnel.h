// Fresnel reflectance of a smooth interface, exact for unpolarised light, from the
// complex relative refractive index η = n + ik of the medium below over the medium
// above (air). From Maxwell's equations (e.g. M. Born and E. Wolf, Principles of
// Optics, §1.5 and §14.2); the complex-arithmetic form is the one pbrt-v4 uses
// (FrComplex, M. Pharr, W. Jakob, G. Humphreys, Physically Based Rendering, 4th ed.,
// §9.5): it is the same formula for dielectrics (k = 0) and conductors.
//
// Also the reflectance and transmittance of a plane-parallel pane (two interfaces
// and the absorbing glass between), summing the multiple reflections inside it.
#pragma once

#include <complex>

namespace skylit {

// Power reflectances for light polarised perpendicular (s, TE) and parallel (p, TM)
// to the plane of incidence.
struct FresnelSP {
  double s = 0;
  double p = 0;
  double unpolarised() const { return 0.5 * (s + p); }
};

// At incidence cos_incident = cos θ_i in [0, 1] (clamped) from the outside, onto a
// medium of relative index eta = n + ik (k ≥ 0 absorbs). Real eta < 1 (leaving a
// denser medium) past the critical angle gives total internal reflection: 1.
FresnelSP fresnel_sp(double cos_incident, std::complex<double> eta);

inline double fresnel_reflectance(double cos_incident, std::complex<double> eta) {
  return fresnel_sp(cos_incident, eta).unpolarised();
}

// Normal incidence: ((n − 1)² + k²) / ((n + 1)² + k²).
double fresnel_normal_incidence(std::complex<double> eta);

// A plane-parallel slab of thickness `thickness_m` with index n + ik in air, lit from
// one side at cos_incident: reflectance (both surfaces and all inner bounces) and
// transmittance, unpolarised. The interfaces use the real n (k ≤ 1e-5 in glass
// changes them by less than 1e-10); the bulk absorbs with α = 4πk/λ along the
// refracted path d / cos θ_t. Per polarisation j, with r_j the single-interface
// reflectance and τ the internal transmittance:
//   R = r + (1 − r)² r τ² / (1 − r² τ²),  T = (1 − r)² τ / (1 − r² τ²)
// (incoherent sum: panes are far thicker than the coherence length of daylight;
// e.g. J. A. Duffie, W. A. Beckman, Solar Engineering of Thermal Processes, ch. 5).
struct PaneOptics {
  double reflectance = 0;
  double transmittance = 0;
};
PaneOptics pane_optics(double cos_incident, double n, double k, double thickness_m, double wavelength_nm);

}  // namespace skylit
