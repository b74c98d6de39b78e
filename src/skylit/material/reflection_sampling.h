// Drawing light directions in proportion to the materials' reflection, for the
// path-traced reference (render/path_integrator.h). The lobes are exactly those the
// fast path evaluates (reflection.h): the Lambertian part albedo(θ_v)/π, drawn
// cosine-weighted; the glossy Cook–Torrance lobe, drawn by its Beckmann half vectors
// (B. Walter et al., "Microfacet models for refraction through rough surfaces", EGSR
// 2007, §5.3: tan²θ_h = −m² ln(1 − u), p(l) = D(h)(n·h) / (4 |v·h|)); and the mirror of
// smooth glass and metal, a direction fixed by the view. One lobe is chosen per sample
// in proportion to an estimate of its reflectance; the density of the non-mirror lobes
// is their mixture (one-sample multiple importance sampling over the lobes).
#pragma once

#include <optional>

#include "skylit/core/vec3.h"
#include "skylit/material/material.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

struct ReflectionSample {
  Vec3 to_light;    // unit
  Spectrum weight;  // f·(n·l)/p (or the mirror's reflectance over its chance): what multiplies
                    // the radiance arriving from to_light
  double pdf = 0;   // sr⁻¹ for the non-mirror lobes; 0 for the mirror (a delta)
  bool mirror = false;
};

// f(l, v)·(n·l) of the lobes other than the mirror, sr⁻¹: albedo(n·v)/π·(n·l) plus the
// glossy lobe's specular_reflection (for a road, the whole r-table BRDF: the reference
// lights roads from the sky by the table too, where the fast path takes its mean Q0).
// 0 below the surface.
CosineWeightedBrdf reflection_cos(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer);

// The density (sr⁻¹) with which sample_reflection draws to_light through the non-mirror
// lobes, the lobes' choice included (for weighing it against other strategies).
double reflection_pdf(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer);

// A direction from three uniform numbers in [0, 1): u_lobe chooses the lobe, u1 and u2
// place the direction in it. None when the material reflects nothing toward this view
// (or the viewer is below the surface).
std::optional<ReflectionSample> sample_reflection(const Material& material, const Vec3& n, const Vec3& to_viewer,
                                                  double u_lobe, double u1, double u2);

// Two unit vectors that make (t, b, n) a right-handed orthonormal frame (Duff et al.,
// "Building an orthonormal basis, revisited", JCGT 2017).
void orthonormal_frame(const Vec3& n, Vec3& t, Vec3& b);

}  // namespace skylit
