// Where a camera ray meets a surface.
#pragma once

#include <cstdint>

#include "skylit/core/vec3.h"

namespace skylit {

struct SurfacePoint {
  Vec3 position;
  Vec3 normal;        // unit, facing the camera
  double distance;    // from the camera
  uint32_t material;  // index into the scene's materials
};

}  // namespace skylit
