// The clear air in the scene's shadows (docs/atmosphere.md, "The air in the buildings'
// shadows"). The aerial perspective table gives the light the air between the camera
// and a surface adds as if all of that air were sunlit. Where the view passes through
// a building's shadow its air scatters no sunbeam: looking along a street in shade
// toward a 30° sun, the sunbeam's single scattering adds about 2.8 cd/m² per metre of
// view, +3 to +5 % on a shaded wall across a canyon (measured against Blender's Cycles,
// 2026-12-07). This takes it out over the parts of the view the sun's shadow volumes
// (geometry/sun_shadow_volumes.h) put in shadow, exactly as the fog's beams are cut
// (Kaneda et al. 1991 §5). What the shadowed air still scatters of the sky's light is
// left as the table has it (the open sky's, a smaller term; the canyon's walls hide
// part of it).
#pragma once

#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/geometry/sun_shadow_volumes.h"
#include "skylit/spectrum/medium_stretch.h"

namespace skylit {

class ShadowedAir {
 public:
  // The meshes' shadow volumes for the sky's sun as seen (SkyModel::to_sun). `sky`
  // must outlive this.
  ShadowedAir(const std::vector<const TriangleMesh*>& meshes, const SkyModel& sky);

  // `air`, the aerial perspective from the ray's origin to `distance_m` along it (unit
  // direction), without the sun's single scattering over the parts in shadow. Const and
  // safe from many threads.
  MediumStretch in_shadows(const MediumStretch& air, const Ray& ray, double distance_m) const;

  // The sun's single scattering the shadowed parts of [0, distance_m] would have added.
  Radiance hidden_sunlight(const Ray& ray, double distance_m) const;

 private:
  const SkyModel& sky_;
  SunShadowVolumes shadows_;
};

}  // namespace skylit
