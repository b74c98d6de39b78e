// The illuminance (lx) on the surface that each pixel's centre sees: what an
// illuminance meter laid on that surface would read, on the side facing the camera —
// the sun if it reaches it, the sky (hidden by obstacles, replaced by their light, as
// the bands method finds it: sky/sky_light.h) and the lamps. For the EXR's data layer,
// the statistics and false colour (docs/statistics.md). 0 where a pixel sees the sky.
#pragma once

#include <vector>

#include "skylit/render/bands_integrator.h"

namespace skylit {

// Row by row from the top, in parallel. The sky's share comes through the same sparse
// cache the image loop uses (render/surface_cache.h), so it costs about what the
// render's sky-light pass costs.
std::vector<float> surface_illuminance(const PreparedScene& scene, const BandsIntegrator& integrator);

}  // namespace skylit
