// A city model's appearances (city_model.h: X3D materials, image textures) as model
// materials (material/model_material.h), the same path glTF and OBJ materials take to
// become skylit materials, so that their colours become reflectance spectra by the
// Jakob–Hanika fit and their textures are read through the triangles' texture
// coordinates. docs/city-models.md gives the mapping.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "skylit/io/city/city_model.h"
#include "skylit/material/model_material.h"
#include "skylit/material/texture.h"

namespace skylit {

// An X3D material as a model material: transparency above 0.01 → a glass pane; a
// specular colour with no diffuse one → a metal of that colour; any specular colour →
// a coat over the diffuse body (Phong exponent 128 × shininess, as X3D defines it);
// otherwise diffuse. Colours are taken as linear reflectances (X3D's lighting
// equations multiply them with light linearly). emissiveColor is a relative glow for
// viewers without light, not a luminance, and is not read; nor is isSmooth.
ModelMaterial model_material_from_x3d(const CityMaterial& material);

// The model's texture images, each read once from the model's folder (sRGB, as
// photographs of facades are); those that are missing are listed instead.
class CityTextureImages {
 public:
  explicit CityTextureImages(std::filesystem::path folder) : folder_(std::move(folder)) {}

  // The image, or null when its file does not exist. Throws InputError, naming the
  // file, for one that exists but is not a PNG or JPEG image.
  std::shared_ptr<const Texture> image(const CityTexture& texture);
  // The images not found, each once, as the model names them.
  const std::vector<std::string>& missing() const { return missing_; }

 private:
  std::filesystem::path folder_;
  std::map<std::string, std::shared_ptr<const Texture>> read_;
  std::vector<std::string> missing_;
};

}  // namespace skylit
