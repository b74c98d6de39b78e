// What the centre of each pixel sees besides its light: the object, how far, and the
// surface's normal. For the EXR's data layers and per-object statistics.
#pragma once

#include <cstdint>
#include <vector>

#include "skylit/render/prepared_scene.h"

namespace skylit {

struct PixelLayers {
  static constexpr int32_t kNoObject = -1;  // the sky
  static constexpr int32_t kNotSeen = -2;   // outside a fisheye's image circle
  int width = 0, height = 0;
  std::vector<int32_t> object;    // index into Scene::objects (or the above), rows from the top
  std::vector<float> distance_m;  // from the camera; 0 where no object
  std::vector<float> normal;      // 3 per pixel, world frame, facing the camera; 0 where no object
  // lx on the surface seen (render/surface_illuminance.h); 0 where no object; empty: not computed
  std::vector<float> illuminance_lx;
  // lx of that from sunlight reflected by glass and metal facades alone, lobes narrower
  // than kBroadLobeRoughness (render/reflected_sun.h); empty: not computed
  std::vector<float> reflected_sun_lx;
};

// One ray through each pixel's centre, in parallel.
PixelLayers trace_pixel_layers(const PreparedScene& scene);

}  // namespace skylit
