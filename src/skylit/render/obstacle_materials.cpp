#include "skylit/render/obstacle_materials.h"

#include "skylit/material/texture.h"
#include "skylit/spectrum/rgb_spectrum_table.h"

namespace skylit {

std::array<float, 3> mean_base_color(const SurfaceAppearance& appearance) {
  std::array<float, 3> color{};
  if (!appearance.base_color) return color;
  const Rgba mean = appearance.base_color->mean();
  for (size_t i = 0; i < 3; ++i) color[i] = static_cast<float>(appearance.base_color_factor[i]) * mean[i];
  return color;
}

std::vector<Material> obstacle_materials(const std::vector<NamedMaterial>& materials) {
  std::vector<Material> seen;
  seen.reserve(materials.size());
  for (const NamedMaterial& named : materials) {
    const SurfaceAppearance* appearance = named.appearance.get();
    if (appearance && appearance->textured())
      seen.push_back(
          with_body_reflectance(named.material, rgb_spectrum_table().reflectance(mean_base_color(*appearance))));
    else
      seen.push_back(named.material);
  }
  return seen;
}

}  // namespace skylit
