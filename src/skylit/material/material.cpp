// The materials' precomputed Fresnel tables and albedo factors (material.h gives the
// models and their sources).
#include "skylit/material/material.h"

#include <algorithm>
#include <stdexcept>

#include "skylit/material/fresnel.h"

namespace skylit {

CookTorranceMaterial::CookTorranceMaterial(const ComplexIor& ior, double roughness, const Spectrum& diffuse_reflectance)
    : ior_(ior),
      roughness_(roughness),
      diffuse_reflectance_(diffuse_reflectance),
      has_diffuse_(!diffuse_reflectance.is_black()) {
  if (!(roughness >= 0)) throw std::invalid_argument("CookTorranceMaterial: roughness must be ≥ 0");
  if (ior.is_conductor() && has_diffuse())
    throw std::invalid_argument("CookTorranceMaterial: a conductor has no diffuse part");
  fresnel_ = std::make_shared<const AngularTable>([&](double cos_theta) {
    Spectrum f;
    for (int i = 0; i < Spectrum::size(); ++i) f[i] = static_cast<float>(fresnel_reflectance(cos_theta, ior.at(i)));
    return f;
  });
  set_diffuse_factor();
}

void CookTorranceMaterial::set_diffuse_factor() {
  const Spectrum f_normal = fresnel_->at(1.0);
  for (int i = 0; i < Spectrum::size(); ++i) {
    const float transmitted = 1.0f - f_normal[i];
    diffuse_factor_[i] = std::min(diffuse_reflectance_[i], transmitted) / transmitted;
  }
}

CookTorranceMaterial CookTorranceMaterial::with_diffuse_reflectance(const Spectrum& diffuse_reflectance) const {
  if (!has_diffuse_) return *this;
  CookTorranceMaterial copy = *this;
  copy.diffuse_reflectance_ = diffuse_reflectance;
  copy.set_diffuse_factor();
  return copy;
}

GlassMaterial::GlassMaterial(const ComplexIor& ior, double thickness_m, double roughness,
                             const Spectrum& interior_reflectance)
    : ior_(ior), thickness_m_(thickness_m), roughness_(roughness), interior_reflectance_(interior_reflectance) {
  if (!(roughness >= 0) || !(thickness_m >= 0))
    throw std::invalid_argument("GlassMaterial: roughness and thickness must be ≥ 0");
  const auto pane = [&](double cos_theta, bool transmitted) {
    Spectrum out;
    for (int i = 0; i < Spectrum::size(); ++i) {
      const PaneOptics p = pane_optics(cos_theta, ior.n[i], ior.k[i], thickness_m, kGrid.center_nm(i));
      out[i] = static_cast<float>(transmitted ? p.transmittance : p.reflectance);
    }
    return out;
  };
  reflectance_ = std::make_shared<const AngularTable>([&](double c) { return pane(c, false); });
  transmittance_ = std::make_shared<const AngularTable>([&](double c) { return pane(c, true); });
  interior_albedo_factor_ = interior_reflectance * transmittance_->hemispherical_mean();
}

}  // namespace skylit
