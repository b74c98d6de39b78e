// The moon as a scene sets it for the sky model (moon_light.h, docs/night-sky.md).
#pragma once

#include "skylit/core/vec3.h"

namespace skylit {

// Where the moon is and how it is lit, as the ephemeris gives it (sun/moon_position.h).
struct MoonSettings {
  double phase_angle_deg = 0;   // sun–moon–earth, 0 full, 180 new
  double distance_km = 384400;  // geocentric
  double angular_radius_deg = 0.259;
  Vec3 to_sun{0, 0, -1};  // world direction toward the sun (below the horizon at night)
};

}  // namespace skylit
