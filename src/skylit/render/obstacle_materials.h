// The materials that obstacles show to the sky light's bounces (bands_integrator.h):
// a ray toward the sky stands for a whole sky element (about 6° wide with 1024
// directions, 13° with 256), which spans far more than a texture's detail at the
// distances between buildings. A textured material is therefore seen by its texture's
// mean colour, turned into a reflectance spectrum once per material, instead of a
// filtered look-up and a spectrum fit for every obstacle ray. (Normal maps are left out
// for the same reason; emission does not light other surfaces in the sky light anyway.)
#pragma once

#include <array>
#include <vector>

#include "skylit/material/material.h"
#include "skylit/material/surface_appearance.h"

namespace skylit {

// The body colour a textured appearance has on average (linear sRGB): its factor times
// the texture's mean.
std::array<float, 3> mean_base_color(const SurfaceAppearance& appearance);

// Per material of the scene (same indices), the material an obstacle ray sees.
std::vector<Material> obstacle_materials(const std::vector<NamedMaterial>& materials);

}  // namespace skylit
