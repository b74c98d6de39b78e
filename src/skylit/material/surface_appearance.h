// What a model file's material adds to a skylit material (material.h): colour that
// varies over the surface (a base-colour texture), and light the surface gives off
// itself (emission, docs/model-materials.md). Read at each surface point through the
// triangle's texture coordinates (PreparedScene::surface_point).
#pragma once

#include <array>
#include <memory>

#include "skylit/material/material.h"
#include "skylit/material/texture.h"
#include "skylit/spectrum/color_space.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

struct SurfaceAppearance {
  // The body's colour is base_color_factor × the texture's texel (linear sRGB, as glTF
  // multiplies them), replacing the material's own colour where a texture is given.
  Rgb base_color_factor{1, 1, 1};
  std::shared_ptr<const Texture> base_color{};
  // Emitted luminance per linear sRGB channel, cd/m² (emissive factor × strength),
  // times the emission texture's texel where one is given.
  Rgb emission_cd_m2{0, 0, 0};
  std::shared_ptr<const Texture> emission{};

  // Faces seen from behind are invisible to camera and bounce rays (glTF doubleSided
  // false); they still cast shadows (docs/model-materials.md).
  bool single_sided = false;
  // A hole wherever alpha_factor × channel alpha_channel of `alpha` (or alpha_factor alone
  // without a texture) is below alpha_cutoff; alpha_cutoff 0: no holes.
  float alpha_cutoff = 0;
  float alpha_factor = 1;
  std::shared_ptr<const Texture> alpha{};
  int alpha_channel = 3;
  // A tangent-space normal map (linear texels, x right along u, y toward the image's top
  // row, z out of the surface) and the scale of its x and y.
  std::shared_ptr<const Texture> normal_map{};
  float normal_scale = 1;

  bool textured() const { return base_color != nullptr; }
  bool cuts_rays() const { return single_sided || alpha_cutoff > 0; }
  bool emissive() const { return emission_cd_m2[0] > 0 || emission_cd_m2[1] > 0 || emission_cd_m2[2] > 0; }
};

// The material with its body's reflectance replaced: a diffuse surface's reflectance, a
// coated one's body under the coat. Metals and glass have no body and are returned
// unchanged (their colour stays the factor's; docs/model-materials.md).
Material with_body_reflectance(const Material& material, const Spectrum& reflectance);

// The radiance of a surface emitting `luminance_cd_m2` per linear sRGB channel: the
// smooth spectrum of the colour's chromaticity (its Jakob–Hanika reflectance of the
// normalised colour) times D65, sRGB's white, scaled so that its luminance is the
// colour's luminance Y.
Radiance emitted_radiance(const std::array<float, 3>& luminance_cd_m2);

// The coverage at texture coordinates (u, v) (bilinear on the finest level, the same for
// camera and shadow rays, so a hole seen is a hole the sun shines through): whether the
// surface is there. `has_uv` false: the texture's mean is used.
bool covers(const SurfaceAppearance& a, bool has_uv, double u, double v);

}  // namespace skylit
