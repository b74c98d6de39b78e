// What the renderer asks of a material at a surface point: the Lambertian part as an
// albedo, the glossy specular part as BRDF × cos for one incident direction, the
// mirror part for smooth surfaces, and cheap measures of the specular lobe for the
// paper's adaptive search over the sky (§4.2). Models and sources: material.h,
// microfacet.h, fresnel.h; docs/materials.md.
//
// Directions are unit vectors pointing away from the surface: n the normal on the
// viewer's side, to_light toward the light (a sky element, the sun), to_viewer toward
// the eye. Radiance toward the viewer is
//   lambertian_radiance(diffuse_albedo(m, n·v), irradiance)
//   + Σ over light directions specular_reflection(m, n, l, v).reflect(L(l), dω(l))
//     (for the sun: specular_reflection(m, n, l, v).reflect(E_normal))
//   + mirror_reflectance(m, n, v) × L(mirror_direction(n, v))   (when it has one).
// The types (radiometry.h) admit only these combinations.
#pragma once

#include <optional>

#include "skylit/core/vec3.h"
#include "skylit/material/material.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// The Lambertian part's hemispherical reflectance at view cosine cos_view = n·v (for
// `diffuse` the reflectance itself; for a coated base and the room behind glass it
// falls toward grazing views, where the interface reflects more).
Reflectance diffuse_albedo(const Material& material, double cos_view);

// The glossy specular BRDF f_s(l, v), sr⁻¹. Zero for `diffuse` and for mirrors.
Spectrum specular_brdf(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer);

// f_s(l, v) (n·l): what reflects incident radiance L(l) dω (sr⁻¹) toward the viewer;
// for the sun or a lamp, their irradiance on a plane facing them.
CosineWeightedBrdf specular_reflection(const Material& material, const Vec3& n, const Vec3& to_light,
                                       const Vec3& to_viewer);

// Whether specular_reflection can be non-zero: a glossy lobe to integrate.
bool has_specular(const Material& material);

// What a point source (a lamp, the sun) adds beyond the Lambertian part
// diffuse_albedo/π·(n·l): the glossy lobe's specular_reflection, and for a road the
// r-table's departure from its mean, (f_road(l, v) − Q0)(n·l) (road_reflection.h),
// which is negative where the table is below its mean: only the sum with the
// Lambertian part is a reflection. Sky light on a road takes the Lambertian part alone
// (Q0 is the table's mean over the directions of incidence).
bool has_point_light_lobe(const Material& material);
CosineWeightedBrdf point_light_reflection(const Material& material, const Vec3& n, const Vec3& to_light,
                                          const Vec3& to_viewer);
// Its mean over bins (a scalar for ordering the lamps).
double point_light_weight(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer);

// The mean over bins of specular_reflection (the same value, without building the
// spectrum): a scalar for deciding where the lobe still matters.
double specular_weight(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer);

// The angle, radians, between the mirror direction of the view and a light direction
// beyond which the lobe's facet distribution D is below 1e-3 of its peak: twice the
// half-vector angle where D(α)/D(0) = 1e-3 (reflecting about h turns the reflected
// direction by at most twice the turn of h). 0 for `diffuse` and mirrors. For
// m = 0.1 it is 0.52 rad (30°), for m = 0.15 0.77 rad (44°). Near grazing, F and
// 1/(n·v) make the lobe's far side relatively larger; G cuts it at the horizon.
double specular_lobe_radius(const Material& material);

// The glossy lobe's Beckmann roughness m; 0 for `diffuse` and mirrors.
double specular_roughness(const Material& material);

// For a smooth surface (roughness below kMirrorRoughness): its spectral mirror
// reflectance at the view angle, to multiply the radiance arriving from
// mirror_direction(n, to_viewer). nullopt for other materials (and when n·v ≤ 0).
std::optional<Reflectance> mirror_reflectance(const Material& material, const Vec3& n, const Vec3& to_viewer);

// The specular part's Fresnel reflectance at the view cosine (a mirror's exactly; for a
// glossy lobe, what it reflects of a smooth surrounding, short of the light its facets
// shadow and mask); black for materials without one. For light that a facade mirrors
// onto others (render/bands_integrator.h).
Reflectance specular_fresnel(const Material& material, double cos_view);

// The direction of perfect reflection of the view about n: 2 (n·v) n − v.
inline Vec3 mirror_direction(const Vec3& n, const Vec3& to_viewer) { return 2 * dot(n, to_viewer) * n - to_viewer; }

}  // namespace skylit
