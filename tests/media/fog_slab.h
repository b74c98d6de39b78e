// A fog layer of uniform density 1 from the ground to `top_m` whose vertical optical
// depth is `optical_depth` in every bin (b = 0): the slab of the radiative-transfer tests.
#pragma once

#include <limits>

#include "skylit/media/fog_settings.h"

namespace skylit::testing {

inline FogSettings uniform_fog_slab(double optical_depth, double top_m) {
  FogSettings fog;
  fog.density_at_ground = 1.0;
  fog.unit_density_extinction_per_m = optical_depth / top_m;
  fog.scale_height_m = std::numeric_limits<double>::infinity();
  fog.bottom_altitude_m = 0;
  fog.top_altitude_m = top_m;
  return fog;
}

}  // namespace skylit::testing
