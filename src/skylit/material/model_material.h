// Materials as model files describe them (glTF 2.0, OBJ + MTL), reduced to the few
// kinds skylit renders, and turned into skylit materials. The readers in io/model/
// map each format's parameters onto ModelMaterial (docs/model-materials.md gives
// every mapping); material_from_model does the physics once for both.
#pragma once

#include <memory>
#include <string>

#include "skylit/material/material.h"
#include "skylit/material/surface_appearance.h"
#include "skylit/material/texture.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {

struct ModelMaterial {
  enum class Kind {
    diffuse,  // Lambertian body of reflectance `color`
    coated,   // a dielectric coat of index `ior` over a body of reflectance `color`
    metal,    // a conductor whose reflectance at normal incidence is `color`
    glass,    // a pane of index `ior` and thickness `thickness_m` (the dark room behind)
  };
  std::string name;  // as the file names it
  Kind kind = Kind::diffuse;
  Rgb color_linear{0.8, 0.8, 0.8};  // linear sRGB, each in [0, 1]
  double roughness = 0.5;           // Beckmann rms slope m (microfacet.h)
  double ior = 1.5;
  double thickness_m = 0.006;
  // The base colour's texture (glTF baseColorTexture, MTL map_Kd), multiplied by
  // color_linear; null for none.
  std::shared_ptr<const Texture> color_texture{};
  // Emitted luminance per linear sRGB channel, cd/m² (glTF emissiveFactor × strength,
  // MTL Ke), times the emission texture where given (docs/model-materials.md).
  Rgb emission_cd_m2{0, 0, 0};
  std::shared_ptr<const Texture> emission_texture{};
  // glTF doubleSided; OBJ has no such flag and its faces are two-sided.
  bool double_sided = true;
  // Cut-outs (glTF alphaMode, MTL map_d; docs/model-materials.md): where
  // alpha_factor × the alpha texture's channel `alpha_channel` (3 = alpha) falls below
  // alpha_cutoff the surface is a hole. alpha_cutoff 0: opaque.
  double alpha_cutoff = 0;
  double alpha_factor = 1;
  std::shared_ptr<const Texture> alpha_texture{};
  int alpha_channel = 3;
  // A tangent-space normal map (glTF normalTexture, MTL norm / map_Bump -bm), linear,
  // its x and y scaled by normal_scale; null for none.
  std::shared_ptr<const Texture> normal_texture{};
  double normal_scale = 1;
};

const char* kind_name(ModelMaterial::Kind kind);

// What `skylit info` says a file's material became: its kind and what it carries, e.g.
// "layered; colour 0.80 0.62 0.50 × texture; m 0.25; n 1.50; normal map; one-sided".
std::string describe(const ModelMaterial& m);

// The skylit material: diffuse → DiffuseMaterial; coated → CookTorranceMaterial over
// the body; metal → CookTorranceMaterial with n, k found so that the Fresnel
// reflectance at normal incidence is `color` in every wavelength bin (see .cpp);
// glass → GlassMaterial. Colours become smooth spectra by the Jakob–Hanika fit.
// A metal's colour is color_linear × its texture's mean (metals are not textured per
// point).
Material material_from_model(const ModelMaterial& m);

// What the model material adds that varies over the surface, shines or cuts rays; null
// when it has no base-colour texture (on a diffuse or coated kind), no emission, no
// normal map, no cut-outs and two sides.
std::shared_ptr<const SurfaceAppearance> appearance_from_model(const ModelMaterial& m);

// n and k of a conductor whose normal-incidence reflectance is r and whose
// reflectance toward grazing is tinted by g (O. Gulbrandsen, "Artist friendly metallic
// Fresnel", JCGT 3(4), 2014, Eqs. 3 and 4). r is limited to [0, 0.999].
ComplexIor conductor_from_reflectance(const Spectrum& r, const Spectrum& g);

// The glTF metallic-roughness roughness (perceptual, α = roughness²) as a Beckmann
// rms slope, and the Blinn–Phong exponent of MTL's Ns likewise.
double beckmann_from_gltf_roughness(double roughness);
double beckmann_from_phong_exponent(double ns);

}  // namespace skylit
