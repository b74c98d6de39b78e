// The named material presets a scene may use instead of stating a material
// (`"walls": "tile"`, or `{"preset": "aluminium", "roughness": 0.1}` to change some of
// its values). Each preset is the scene-file JSON it stands for, so a user can read
// exactly what it means and copy it; io/material_reader.cpp reads it like any other
// material. Values and their sources: docs/materials.md.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace skylit {

struct MaterialPreset {
  std::string_view name;
  std::string_view json;  // a material object with a "type", as in a scene file
};

// tile, aluminium, glass, concrete, asphalt, grass.
const std::vector<MaterialPreset>& material_presets();

// nullptr if there is none of that name.
const MaterialPreset* find_material_preset(std::string_view name);

// "tile, aluminium, …" for messages.
std::string material_preset_names();

}  // namespace skylit
