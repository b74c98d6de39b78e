// The ray tracer's view of a scene object whose materials cut rays
// (surface_appearance.h): texels masked out by alpha are holes for every ray, camera,
// bounce, shadow and sky occlusion alike, so a foliage card or a railing casts the
// dappled shadow its texture draws; faces of one-sided materials seen from behind are
// passed by camera and bounce rays but still stop shadow rays, as a real sheet would
// (docs/model-materials.md).
#pragma once

#include <memory>
#include <vector>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/material/material.h"
#include "skylit/scene/scene.h"

namespace skylit {

class SurfaceCutouts final : public HitFilter {
 public:
  // Keeps references to both, which must outlive it.
  SurfaceCutouts(const SceneObject& object, const std::vector<NamedMaterial>& materials)
      : object_(object), materials_(materials) {}
  bool accepts(uint32_t triangle, float u, float v, const Vec3& direction, const Vec3& geometric_normal,
               bool shadow) const override;

 private:
  const SceneObject& object_;
  const std::vector<NamedMaterial>& materials_;
};

// The filter an object needs, or null when none of its materials cuts rays (then its
// rays cost nothing extra).
std::unique_ptr<SurfaceCutouts> surface_cutouts_for(const SceneObject& object,
                                                    const std::vector<NamedMaterial>& materials);

}  // namespace skylit
