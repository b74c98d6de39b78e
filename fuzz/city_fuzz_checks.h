// What both city readers promise the placement about appearances, checked on every
// input they accept: indices in range, and a textured surface's coordinates one per
// point of each ring (the placement indexes them by the triangulation's points).
#pragma once

#include <cstdlib>

#include "skylit/io/city/city_model.h"

namespace skylit::fuzz {

inline void check_city_appearances(const CityModel& model) {
  for (const CityObject& object : model.objects)
    for (const CitySurface& surface : object.surfaces) {
      if (surface.material != CitySurface::kNone &&
          (surface.material < 0 || static_cast<size_t>(surface.material) >= model.materials.size()))
        abort();
      if (surface.texture == CitySurface::kNone) continue;
      if (surface.texture < 0 || static_cast<size_t>(surface.texture) >= model.textures.size()) abort();
      if (surface.texture_coordinates.size() != surface.rings.size()) abort();
      for (size_t r = 0; r < surface.rings.size(); ++r)
        if (surface.texture_coordinates[r].size() != surface.rings[r].size()) abort();
    }
}

}  // namespace skylit::fuzz
