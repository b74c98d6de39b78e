#include "skylit/material/model_material.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/formatted.h"
#include "skylit/spectrum/rgb_to_spectrum.h"

namespace skylit {

const char* kind_name(ModelMaterial::Kind kind) {
  switch (kind) {
    case ModelMaterial::Kind::diffuse:
      return "diffuse";
    case ModelMaterial::Kind::coated:
      return "layered";
    case ModelMaterial::Kind::metal:
      return "metal";
    case ModelMaterial::Kind::glass:
      return "glass";
  }
  return "?";
}

std::string describe(const ModelMaterial& m) {
  std::string out = kind_name(m.kind);
  if (m.kind != ModelMaterial::Kind::glass) {
    out += formatted("; colour %.2f %.2f %.2f", m.color_linear[0], m.color_linear[1], m.color_linear[2]);
    if (m.color_texture) out += m.kind == ModelMaterial::Kind::metal ? " × its texture's mean" : " × texture";
  }
  if (m.kind != ModelMaterial::Kind::diffuse) out += formatted("; m %.2f", m.roughness);
  if (m.kind == ModelMaterial::Kind::coated || m.kind == ModelMaterial::Kind::glass)
    out += formatted("; n %.2f", m.ior);
  const double emission = std::max({m.emission_cd_m2[0], m.emission_cd_m2[1], m.emission_cd_m2[2]});
  if (emission > 0) out += formatted("; emits up to %.4g cd/m²", emission) + (m.emission_texture ? " × texture" : "");
  if (m.alpha_cutoff > 0) out += formatted("; cut out where alpha < %.2f", m.alpha_cutoff);
  if (m.normal_texture) out += "; normal map";
  if (!m.double_sided) out += "; one-sided";
  return out;
}

ComplexIor conductor_from_reflectance(const Spectrum& r, const Spectrum& g) {
  ComplexIor ior{Spectrum(), Spectrum()};
  for (int i = 0; i < Spectrum::size(); ++i) {
    const double ri = std::clamp(static_cast<double>(r[i]), 0.0, 0.999);
    const double gi = std::clamp(static_cast<double>(g[i]), 0.0, 1.0);
    const double root = std::sqrt(ri);
    // Eq. 3: n between the edge-tint extremes; Eq. 4: k from r and n, chosen so that
    // ((n − 1)² + k²) / ((n + 1)² + k²) = r exactly.
    const double n = gi * (1 - ri) / (1 + ri) + (1 - gi) * (1 + root) / (1 - root);
    const double k2 = (ri * (n + 1) * (n + 1) - (n - 1) * (n - 1)) / (1 - ri);
    ior.n[i] = static_cast<float>(n);
    ior.k[i] = static_cast<float>(std::sqrt(std::max(k2, 0.0)));
  }
  return ior;
}

// Walter et al., "Microfacet models for refraction through rough surfaces" (EGSR
// 2007), §5.2: the GGX and Beckmann width parameters α give lobes of nearly the same
// shape, so the rms slope is taken equal to glTF's α = roughness² (glTF 2.0 spec,
// Appendix B).
double beckmann_from_gltf_roughness(double roughness) {
  const double r = std::clamp(roughness, 0.0, 1.0);
  return r * r;
}

// Walter et al. (2007) Eq. 37: a Phong exponent α_p matches a Beckmann lobe of
// α_b = √(2 / (α_p + 2)).
double beckmann_from_phong_exponent(double ns) { return std::sqrt(2.0 / (std::max(ns, 0.0) + 2.0)); }

Material material_from_model(const ModelMaterial& m) {
  Rgb color = m.color_linear;
  if (m.color_texture && m.kind == ModelMaterial::Kind::metal) {
    const Rgba mean = m.color_texture->mean();
    for (size_t i = 0; i < 3; ++i) color[i] *= mean[i];
  }
  for (double& c : color) c = std::isfinite(c) ? std::clamp(c, 0.0, 1.0) : 0.0;
  const double roughness = std::isfinite(m.roughness) ? std::clamp(m.roughness, 0.0, 1.0) : 0.5;
  const double ior = std::isfinite(m.ior) ? std::clamp(m.ior, 1.0, 4.0) : 1.5;
  switch (m.kind) {
    case ModelMaterial::Kind::diffuse:
      return DiffuseMaterial{reflectance_from_linear_srgb(color)};
    case ModelMaterial::Kind::coated:
      return CookTorranceMaterial(constant_ior(ior), roughness, reflectance_from_linear_srgb(color));
    case ModelMaterial::Kind::metal: {
      // The edge tint is the colour itself: gold stays gold toward grazing, as
      // measured metals do.
      const Spectrum f0 = reflectance_from_linear_srgb(color);
      return CookTorranceMaterial(conductor_from_reflectance(f0, f0), roughness);
    }
    case ModelMaterial::Kind::glass: {
      const double thickness = std::isfinite(m.thickness_m) ? std::clamp(m.thickness_m, 0.0, 0.1) : 0.006;
      // The same dark room as the `glass` preset (docs/materials.md).
      return GlassMaterial(constant_ior(ior), thickness, roughness, Spectrum(0.05f));
    }
  }
  return DiffuseMaterial{reflectance_from_linear_srgb(color)};
}

std::shared_ptr<const SurfaceAppearance> appearance_from_model(const ModelMaterial& m) {
  SurfaceAppearance a;
  const bool has_body = m.kind == ModelMaterial::Kind::diffuse || m.kind == ModelMaterial::Kind::coated;
  if (has_body && m.color_texture) {
    a.base_color = m.color_texture;
    for (size_t i = 0; i < 3; ++i) {
      const double c = m.color_linear[i];
      a.base_color_factor[i] = std::isfinite(c) ? std::clamp(c, 0.0, 1.0) : 0.0;
    }
  }
  for (size_t i = 0; i < 3; ++i) {
    const double e = m.emission_cd_m2[i];
    // Up to 1e9 cd/m², the sun's disc: beyond any lit surface, and finite in float.
    a.emission_cd_m2[i] = std::isfinite(e) ? std::clamp(e, 0.0, 1e9) : 0.0;
  }
  if (a.emissive()) a.emission = m.emission_texture;
  a.single_sided = !m.double_sided;
  if (m.alpha_cutoff > 0 && std::isfinite(m.alpha_cutoff)) {
    a.alpha_cutoff = static_cast<float>(std::min(m.alpha_cutoff, 1.0));
    a.alpha_factor = std::isfinite(m.alpha_factor) ? static_cast<float>(std::clamp(m.alpha_factor, 0.0, 1.0)) : 1.0f;
    a.alpha = m.alpha_texture;
    a.alpha_channel = m.alpha_channel;
  }
  if (m.normal_texture) {
    a.normal_map = m.normal_texture;
    // Beyond ±10 the map's tilt is all but horizontal anyway; NaN means none.
    a.normal_scale = std::isfinite(m.normal_scale) ? static_cast<float>(std::clamp(m.normal_scale, -10.0, 10.0)) : 1.0f;
  }
  if (!a.textured() && !a.emissive() && !a.cuts_rays() && !a.normal_map) return nullptr;
  return std::make_shared<const SurfaceAppearance>(std::move(a));
}

}  // namespace skylit
