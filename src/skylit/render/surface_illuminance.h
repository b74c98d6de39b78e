// The illuminance (lx) on the surface that each pixel's centre sees: what an
// illuminance meter laid on that surface would read, on the side facing the camera —
// the sun if it reaches it, the sky (hidden by obstacles, replaced by their light, as
// the bands method finds it: sky/sky_light.h), the sun reflected by glass and metal
// facades (render/reflected_sun.h) and the lamps. For the EXR's data layers, the
// statistics and false colour (docs/statistics.md). 0 where a pixel sees the sky.
#pragma once

#include <vector>

#include "skylit/render/bands_integrator.h"

namespace skylit {

struct SurfaceIlluminance {
  std::vector<float> total_lx;          // all of the above, rows from the top
  std::vector<float> reflected_sun_lx;  // the reflected sun's share alone (a glare study's input)
};

// Row by row from the top, in parallel. The sky's share and the rough facades'
// reflected sun come through the same sparse cache the image loop uses
// (render/surface_cache.h), so it costs about what the render's sky-light pass costs.
SurfaceIlluminance surface_illuminance(const PreparedScene& scene, const BandsIntegrator& integrator);

}  // namespace skylit
