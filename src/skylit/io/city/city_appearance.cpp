#include "skylit/io/city/city_appearance.h"

#include <algorithm>

#include "skylit/io/model/texture_file.h"

namespace skylit {

namespace {
double largest(const std::array<double, 3>& rgb) { return std::max({rgb[0], rgb[1], rgb[2]}); }
}  // namespace

ModelMaterial model_material_from_x3d(const CityMaterial& material) {
  ModelMaterial out;
  out.name = material.name;
  out.color_linear = material.diffuse;
  out.roughness = beckmann_from_phong_exponent(128.0 * material.shininess);
  if (material.transparency > 0.01) {
    out.kind = ModelMaterial::Kind::glass;
    out.roughness = 0;  // a pane is flat
  } else if (largest(material.specular) > 0.1 && largest(material.diffuse) < 0.01) {
    out.kind = ModelMaterial::Kind::metal;
    out.color_linear = material.specular;
  } else if (largest(material.specular) > 0) {
    out.kind = ModelMaterial::Kind::coated;
  } else {
    out.kind = ModelMaterial::Kind::diffuse;
  }
  return out;
}

std::shared_ptr<const Texture> CityTextureImages::image(const CityTexture& texture) {
  const auto [it, added] = read_.try_emplace(texture.image, nullptr);
  if (!added) return it->second;
  // The image's name is a relative URI: '/' separates folders on every system.
  const std::filesystem::path file = folder_ / std::filesystem::path(texture.image).lexically_normal();
  std::error_code ec;
  if (std::filesystem::exists(file, ec))
    it->second = read_texture_file(file, TextureEncoding::srgb);
  else
    missing_.push_back(texture.image);
  return it->second;
}

}  // namespace skylit
