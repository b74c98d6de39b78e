// The renderer's view of materials (reflection.h): dispatch over Material to the
// Cook–Torrance lobe, the Fresnel tables and the albedo factors of material.h.
#include "skylit/material/reflection.h"

#include <algorithm>

#include "skylit/core/angles.h"

#include "skylit/material/microfacet.h"

namespace skylit {

namespace {

// The parts shared by the two specular materials: the lobe's roughness and the
// table of its reflectance against cos(v·h) (interface Fresnel, or pane).
struct SpecularPart {
  double roughness;
  const AngularTable* fresnel;
};

std::optional<SpecularPart> specular_part(const Material& material) {
  if (const auto* ct = std::get_if<CookTorranceMaterial>(&material))
    return SpecularPart{ct->roughness(), &ct->fresnel()};
  if (const auto* glass = std::get_if<GlassMaterial>(&material))
    return SpecularPart{glass->roughness(), &glass->reflectance()};
  return std::nullopt;
}

std::optional<SpecularPart> glossy_part(const Material& material) {
  auto part = specular_part(material);
  if (part && part->roughness < kMirrorRoughness) return std::nullopt;
  return part;
}

}  // namespace

Reflectance diffuse_albedo(const Material& material, double cos_view) {
  if (const auto* d = std::get_if<DiffuseMaterial>(&material)) return Reflectance(d->reflectance);
  if (const auto* road = std::get_if<RoadMaterial>(&material))  // Lambertian with f = Q0
    return Reflectance(Spectrum(static_cast<float>(kPi * road->q0())));
  if (const auto* ct = std::get_if<CookTorranceMaterial>(&material)) {
    if (!ct->has_diffuse()) return Reflectance();
    Spectrum out = ct->diffuse_factor();
    const Spectrum f = ct->fresnel().at(cos_view);
    for (int i = 0; i < Spectrum::size(); ++i) out[i] *= 1.0f - f[i];
    return Reflectance(out);
  }
  const auto& glass = std::get<GlassMaterial>(material);
  return Reflectance(glass.interior_albedo_factor() * glass.transmittance().at(cos_view));
}

Spectrum specular_brdf(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) {
  const auto part = glossy_part(material);
  if (!part) return Spectrum();
  const MicrofacetTerm term = cook_torrance_term(n, to_light, to_viewer, part->roughness);
  if (term.brdf_without_fresnel <= 0) return Spectrum();
  return part->fresnel->at(term.cos_view_half) * static_cast<float>(term.brdf_without_fresnel);
}

CosineWeightedBrdf specular_reflection(const Material& material, const Vec3& n, const Vec3& to_light,
                                       const Vec3& to_viewer) {
  return {specular_brdf(material, n, to_light, to_viewer) * static_cast<float>(std::max(0.0, dot(n, to_light)))};
}

bool has_specular(const Material& material) { return glossy_part(material).has_value(); }

namespace {

// (f_road − Q0)(n·l): the road table's part beyond its Lambertian mean.
double road_excess(const RoadMaterial& road, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) {
  const double cos_light = dot(n, to_light);
  if (!(cos_light > 0) || !(dot(n, to_viewer) > 0)) return 0;
  return (road.brdf(n, to_light, to_viewer) - road.q0()) * cos_light;
}

}  // namespace

bool has_point_light_lobe(const Material& material) {
  return has_specular(material) || std::holds_alternative<RoadMaterial>(material);
}

CosineWeightedBrdf point_light_reflection(const Material& material, const Vec3& n, const Vec3& to_light,
                                          const Vec3& to_viewer) {
  if (const auto* road = std::get_if<RoadMaterial>(&material))
    return {Spectrum(static_cast<float>(road_excess(*road, n, to_light, to_viewer)))};
  return specular_reflection(material, n, to_light, to_viewer);
}

double point_light_weight(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) {
  if (const auto* road = std::get_if<RoadMaterial>(&material)) return road_excess(*road, n, to_light, to_viewer);
  return specular_weight(material, n, to_light, to_viewer);
}

double specular_weight(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) {
  const auto part = glossy_part(material);
  if (!part) return 0;
  const MicrofacetTerm term = cook_torrance_term(n, to_light, to_viewer, part->roughness);
  if (term.brdf_without_fresnel <= 0) return 0;
  return part->fresnel->mean_at(term.cos_view_half) * term.brdf_without_fresnel * dot(n, to_light);
}

double specular_roughness(const Material& material) {
  const auto part = glossy_part(material);
  return part ? part->roughness : 0.0;
}

double specular_lobe_radius(const Material& material) {
  const auto part = glossy_part(material);
  return part ? 2 * beckmann_half_angle_at_1e3(part->roughness) : 0.0;
}

Reflectance specular_fresnel(const Material& material, double cos_view) {
  const auto part = specular_part(material);
  if (!part || !(cos_view > 0)) return Reflectance();
  return Reflectance(part->fresnel->at(cos_view));
}

std::optional<Reflectance> mirror_reflectance(const Material& material, const Vec3& n, const Vec3& to_viewer) {
  const auto part = specular_part(material);
  if (!part || part->roughness >= kMirrorRoughness) return std::nullopt;
  const double cos_view = dot(n, to_viewer);
  if (cos_view <= 0) return std::nullopt;
  return Reflectance(part->fresnel->at(cos_view));
}

}  // namespace skylit
