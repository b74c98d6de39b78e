// The materials city surfaces get when the scene names none for their class: a
// default palette keyed by "Type.Semantic" ("Building.RoofSurface"), a semantic alone
// ("RoofSurface": a roof of any object type) or a type alone ("WaterBody"). Each entry
// is scene-file material JSON (docs/scene-format.md, "materials"), a preset's name or
// an inline definition, so that a user can copy and change it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace skylit {

struct CityPaletteEntry {
  std::string_view key;
  std::string_view material_json;
};

const std::vector<CityPaletteEntry>& default_city_palette();

// The palette's entry for a class: "Type.Semantic" itself, else its semantic, else its
// type, else the entry "default".
const CityPaletteEntry& city_palette_entry(const std::string& class_key);

}  // namespace skylit
