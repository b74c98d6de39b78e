#include "skylit/material/surface_appearance.h"

#include <algorithm>
#include <cmath>

#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/illuminants.h"
#include "skylit/spectrum/rgb_spectrum_table.h"

namespace skylit {

Material with_body_reflectance(const Material& material, const Spectrum& reflectance) {
  if (std::holds_alternative<DiffuseMaterial>(material)) return DiffuseMaterial{reflectance};
  if (const auto* coated = std::get_if<CookTorranceMaterial>(&material))
    return coated->with_diffuse_reflectance(reflectance);
  return material;
}

Radiance emitted_radiance(const std::array<float, 3>& luminance_cd_m2) {
  std::array<float, 3> c{};
  for (size_t i = 0; i < 3; ++i) c[i] = std::isfinite(luminance_cd_m2[i]) ? std::max(luminance_cd_m2[i], 0.0f) : 0.0f;
  const float peak = std::max({c[0], c[1], c[2]});
  if (!(peak > 0)) return Radiance(0.0f);
  const double y = xyz_from_linear_srgb({c[0], c[1], c[2]}).y;
  static const Spectrum d65 = Spectrum::from_table(cie_d65_table());
  const Spectrum shape = rgb_spectrum_table().reflectance({c[0] / peak, c[1] / peak, c[2] / peak}) * d65;
  const double shape_luminance = luminance(shape);
  if (!(shape_luminance > 0)) return Radiance(0.0f);
  return Radiance(shape * static_cast<float>(y / shape_luminance));
}

bool covers(const SurfaceAppearance& a, bool has_uv, double u, double v) {
  if (!(a.alpha_cutoff > 0)) return true;
  float alpha = a.alpha_factor;
  if (a.alpha) {
    const size_t channel = static_cast<size_t>(std::clamp(a.alpha_channel, 0, 3));
    alpha *= (has_uv ? a.alpha->bilinear(0, u, v) : a.alpha->mean())[channel];
  }
  return alpha >= a.alpha_cutoff;
}

}  // namespace skylit
