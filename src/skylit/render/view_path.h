// What lies between the camera and what a view ray meets: the air, the fog and the
// clouds, each a stretch of medium, and the one order in which light is seen through
// them (seen_from_camera).
#pragma once

#include "skylit/spectrum/medium_stretch.h"

namespace skylit {

struct ViewPath {
  bool to_sky = false;  // the ray meets no object
  // The air up to a surface (aerial perspective). Not for the sky, whose radiance
  // already holds the air along the whole ray.
  MediumStretch air;
  MediumStretch fog;
  MediumStretch clouds;
  // Sky rays: the air between the camera and the first cloud they enter.
  MediumStretch air_to_clouds;

  // What the camera sees of the light leaving the ray's end toward it (a surface's, or
  // the sky's and the sun's). Clouds are farthest from the camera, the fog nearest; the
  // air's long path is over them all: clouds, then fog, then (for surfaces) the air.
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
    const Radiance through_fog = fog.seen_through(through_clouds);
    if (to_sky) return through_fog;
    return air.seen_through(through_fog);
  }
};

}  // namespace skylit
