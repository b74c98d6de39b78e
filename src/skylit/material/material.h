// Surface materials. For now only the Lambertian `diffuse`; the sky-light issue adds
// Cook–Torrance, glass and layered materials as further alternatives of Material.
#pragma once

#include <string>
#include <variant>

#include "skylit/spectrum/spectrum.h"

namespace skylit {

// A Lambertian reflector: radiance = reflectance / π × irradiance.
struct DiffuseMaterial {
  Spectrum reflectance;  // hemispherical reflectance per bin, in [0, 1]
};

using Material = std::variant<DiffuseMaterial>;

struct NamedMaterial {
  std::string name;
  Material material;
};

}  // namespace skylit
