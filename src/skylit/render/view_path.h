// What lies between the camera and what a view ray meets: the air, the fog and the
// clouds, each a stretch of medium, and the one order in which light is seen through
// them (seen_from_camera).
#pragma once

#include <algorithm>

#include "skylit/media/fog_behind_surface.h"
#include "skylit/spectrum/medium_stretch.h"

namespace skylit {

// What a surface changes in the fog's light in front of it (ViewPath::seen_from_camera).
struct SurfaceFrontInFog {
  FogHiddenBehind hidden;
  Radiance alike_everywhere{0.0f};  // the part of the surface's light sent toward every direction
  bool fog_in_shadow = false;       // the fog just before the surface lies in a shadow of the sun
};

struct ViewPath {
  bool to_sky = false;  // the ray meets no object
  // From the camera to where the fog hides the rest (FogMedium::Along): the air, and
  // the fog mixed with the air that shares its layer (BandsIntegrator::view_path).
  // Without fog, the air up to a surface, and nothing for the sky.
  MediumStretch near;
  // Sky rays: the air's own in-scattered light over that same stretch, which the sky's
  // radiance holds and `near` replaces.
  Radiance air_near{0.0f};
  // Beyond `near`: the air up to a surface (not for the sky, whose radiance already
  // holds it), seen through the rest of the fog.
  MediumStretch air_beyond;
  Transmittance fog_beyond{1.0f};
  Transmittance fog_whole{1.0f};  // the fog's own transmittance along the whole ray
  // Surfaces in a multiply scattering fog: its forward spike's gain on the surface's
  // light and the open layer's radiance it stands for (FogMedium::Along), the air's
  // transmittance in the gain.
  Transmittance fog_forward_gain{0.0f};
  Radiance fog_open_radiance{0.0f};
  // The air's transmittance up to a surface in the fog (for what the surface changes in
  // the fog's light in front of it, FogHiddenBehind).
  Transmittance fog_air_transmittance{1.0f};
  MediumStretch clouds;
  // Sky rays: the air between the camera and the first cloud they enter.
  MediumStretch air_to_clouds;

  // What the camera sees of the light leaving the ray's end toward it (a surface's, or
  // the sky's and the sun's). Clouds are farthest from the camera; the fog lies near the
  // ground, in the air. `front`: what a surface changes in the fog's light in front of it.
  Radiance seen_from_camera(const Radiance& leaving, const SurfaceFrontInFog& front = {}) const {
    if (!to_sky) {
      const Radiance seen = near.seen_through(air_beyond.seen_through(clouds.seen_through(leaving)) * fog_beyond);
      const FogHiddenBehind& hidden = front.hidden;
      if (fog_forward_gain.is_black() && hidden.gain.is_black()) return seen;
      // The hidden light is held without the fog's transmittance to the camera, which
      // is the pixel's own (fog_whole), down to kHiddenHeldDepth.
      Spectrum with_fog = (seen + (leaving - fog_open_radiance) * (fog_forward_gain * clouds.transmittance) +
                           (front.alike_everywhere * hidden.gain - hidden.field_for(front.fog_in_shadow)) *
                               (hidden_light_transmittance(fog_whole) * fog_air_transmittance * clouds.transmittance))
                              .spectrum();
      for (int k = 0; k < kSpectralBins; ++k) with_fog[k] = std::max(0.0f, with_fog[k]);
      return Radiance(with_fog);
    }
    // The sky's radiance holds the air along the whole ray; the clouds replace what lies
    // beyond them and are seen through the air before them (medium_stretch.h).
    const Radiance through_clouds = seen_past(leaving, air_to_clouds, clouds);
    // That is S' = A_near + T_near·S_rest, A_near and T_near the air's over `near`:
    // the fog dims T_near·S_rest, and `near` replaces A_near.
    Spectrum rest = (through_clouds - air_near).spectrum();
    for (int k = 0; k < kSpectralBins; ++k) rest[k] = std::max(0.0f, rest[k]);
    return near.in_scattered + Radiance(rest) * fog_whole;
  }
};

}  // namespace skylit
