// The geometric part of the Cook–Torrance specular BRDF: R. L. Cook and
// K. E. Torrance, "A reflectance model for computer graphics", ACM Trans. Graph. 1(1)
// (1982) 7–24, with the Beckmann distribution of facet slopes (rms slope m, their
// "roughness") and their V-cavity geometric attenuation G (shadowing and masking,
// from Torrance & Sparrow 1967 and Blinn 1977).
//
// The BRDF is f_s(l, v) = D(h) G(l, v) F(v·h) / (4 (n·l)(n·v)) with D normalised so
// that ∫ D(h) (n·h) dω_h = 1 over the hemisphere: the facets' projected area equals
// the surface's. The 4 is the Jacobian from half vector to light direction,
// dω_h = dω_l / (4 v·h). Cook & Torrance printed π instead of 4, with
// D = exp(−tan²α/m²) / (m² cos⁴α), which lacks Beckmann's 1/π; together their
// constants give four times the value above. They fitted the specular part's weight
// to measurements, so its absolute scale did not matter to them; here it does: the
// renderer's radiances are absolute, and with the normalised form a mirror-like
// surface (F = 1, small m) reflects all the light it receives, a rough one less only
// through G (the light that facets shadow and mask), never more (energy).
// B. Walter et al., "Microfacet models for refraction through rough surfaces",
// EGSR 2007, §3–5, give this form.
#pragma once

#include "skylit/core/vec3.h"

namespace skylit {

// Beckmann distribution of facet normals at cos α = n·h, rms slope m > 0, in sr⁻¹:
// D = exp(−tan²α / m²) / (π m² cos⁴α); 0 for n·h ≤ 0.
double beckmann_distribution(double cos_alpha, double m);

// G = min(1, 2(n·h)(n·v)/(v·h), 2(n·h)(n·l)/(v·h)) for unit vectors.
double v_cavity_geometry(const Vec3& n, const Vec3& h, const Vec3& to_light, const Vec3& to_viewer);

// D G / (4 (n·l)(n·v)): the BRDF with F = 1, sr⁻¹, for unit vectors; 0 when the light
// or the viewer is below the surface. The Fresnel factor is taken at v·h, which the
// second member returns (the cosine between viewer and half vector).
struct MicrofacetTerm {
  double brdf_without_fresnel = 0;
  double cos_view_half = 1;
};
MicrofacetTerm cook_torrance_term(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer, double m);

// The angle between the half vector and the normal beyond which D < 1e-3 of its peak
// D(0) (the 1/cos⁴ factor included), radians: tan²α = m² ln(1000 / cos⁴α), solved
// by fixed-point iteration.
double beckmann_half_angle_at_1e3(double m);

}  // namespace skylit
