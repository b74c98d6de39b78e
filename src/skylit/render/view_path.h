// What lies between the camera and what a view ray meets: the air, the fog and the
// clouds, each a stretch of medium, and the one order in which light is seen through
// them (seen_from_camera).
#pragma once

#include <algorithm>

#include "skylit/spectrum/medium_stretch.h"

namespace skylit {

struct ViewPath {
  bool to_sky = false;  // the ray meets no object
  // The air in three stretches around the part of the ray where the fog is seen
  // (FogMedium::Along): up to where the ray enters the layer, from there on while the
  // fog is seen through (mixed with it), and beyond, up to a surface. Without fog, all
  // the air is `air_to_fog`. For the sky only the first two are set: the sky's radiance
  // already holds the air along the whole ray.
  MediumStretch air_to_fog;
  MediumStretch air_in_fog;
  MediumStretch air_beyond_fog;
  MediumStretch fog;               // the fog where it is seen: all its light
  Transmittance fog_beyond{1.0f};  // the rest of the fog, which hides what lies behind it
  MediumStretch clouds;
  // Sky rays: the air between the camera and the first cloud they enter.
  MediumStretch air_to_clouds;

  // What the camera sees of the light leaving the ray's end toward it (a surface's, or
  // the sky's and the sun's). Clouds are farthest from the camera; the fog lies near the
  // ground, in the air, and dims the air's light inside it as the air dims the fog's.
  Radiance seen_from_camera(const Radiance& leaving) const {
    Radiance through_clouds = clouds.seen_through(leaving);
    if (to_sky) {
      // The sky's radiance S holds the air along the whole ray: S = A + T·S_beyond, with
      // A and T the air's in-scatter and transmittance up to the clouds. The clouds
      // replace what lies beyond them and are seen through that air:
      // T·(cloud + t·S_beyond) + A = t·S + (1 − t)·A + T·cloud.
      through_clouds = leaving * clouds.transmittance +
                       air_to_clouds.in_scattered * (Transmittance(1.0f) - clouds.transmittance) +
                       clouds.in_scattered * air_to_clouds.transmittance;
    }
    const MediumStretch near = followed_by(air_to_fog, mixed(air_in_fog, fog));
    if (!to_sky) return near.seen_through(air_beyond_fog.seen_through(through_clouds) * fog_beyond);
    // The sky (with its clouds) is S = A_out + T_out·S_beyond, A_out and T_out the air's
    // up to where the fog stops being seen; T_out·S_beyond is what the fog dims, and
    // A_out is replaced by the air and fog mixed.
    const Radiance air_out = followed_by(air_to_fog, air_in_fog).in_scattered;
    Spectrum beyond = (through_clouds - air_out).spectrum();
    for (int k = 0; k < kSpectralBins; ++k) beyond[k] = std::max(0.0f, beyond[k]);
    return near.in_scattered + Radiance(beyond) * (fog.transmittance * fog_beyond);
  }
};

}  // namespace skylit
