#include "skylit/render/surface_cutouts.h"

#include <algorithm>

#include "skylit/material/surface_appearance.h"

namespace skylit {

bool SurfaceCutouts::accepts(uint32_t triangle, float u, float v, const Vec3& direction, const Vec3& geometric_normal,
                             bool shadow) const {
  const SurfaceAppearance* a = materials_[object_.material_of(triangle)].appearance.get();
  if (a == nullptr || !a->cuts_rays()) return true;
  if (a->single_sided && !shadow && dot(direction, geometric_normal) > 0) return false;
  if (!(a->alpha_cutoff > 0)) return true;
  if (object_.corner_uvs.empty()) return covers(*a, false, 0, 0);
  const CornerUvs& uv = object_.corner_uvs[triangle];
  const double b1 = u, b2 = v, b0 = 1.0 - b1 - b2;
  return covers(*a, true, b0 * uv[0][0] + b1 * uv[1][0] + b2 * uv[2][0], b0 * uv[0][1] + b1 * uv[1][1] + b2 * uv[2][1]);
}

std::unique_ptr<SurfaceCutouts> surface_cutouts_for(const SceneObject& object,
                                                    const std::vector<NamedMaterial>& materials) {
  const auto cuts = [&](uint32_t m) {
    const SurfaceAppearance* a = materials[m].appearance.get();
    return a != nullptr && a->cuts_rays();
  };
  // Materials, not triangles, are checked: a scene has few.
  std::vector<bool> used(materials.size(), false);
  if (object.triangle_materials.empty()) {
    if (object.material_index < used.size()) used[object.material_index] = true;
  } else {
    for (uint32_t m : object.triangle_materials)
      if (m < used.size()) used[m] = true;
  }
  for (uint32_t m = 0; m < materials.size(); ++m)
    if (used[m] && cuts(m)) return std::make_unique<SurfaceCutouts>(object, materials);
  return nullptr;
}

}  // namespace skylit
