// Where a camera ray meets a surface.
#pragma once

#include <array>
#include <cstdint>

#include "skylit/core/vec3.h"

namespace skylit {

struct SurfacePoint {
  Vec3 position;
  Vec3 normal;        // unit, facing the camera
  double distance;    // from the camera
  uint32_t material;  // index into the scene's materials
  // Where the material's appearance varies over the surface or shines
  // (material/surface_appearance.h), what it is at this point.
  bool has_color = false;                 // color replaces the material's body colour
  bool emissive = false;                  // the surface gives off emission_cd_m2
  std::array<float, 3> color{};           // linear sRGB reflectance of the body
  std::array<float, 3> emission_cd_m2{};  // emitted luminance per linear sRGB channel
  // The triangle's own normal, facing the camera, where `normal` is a smooth or mapped
  // one (zero where not known: then `normal` is the plane's).
  Vec3 plane_normal{};
  const Vec3& plane() const { return plane_normal == Vec3{} ? normal : plane_normal; }
};

}  // namespace skylit
