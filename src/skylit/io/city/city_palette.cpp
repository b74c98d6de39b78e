// Reflectances are typical values of the materials named (docs/city-models.md gives
// their sources); a city model says what a surface is, rarely what it is made of.
#include "skylit/io/city/city_palette.h"

namespace skylit {

const std::vector<CityPaletteEntry>& default_city_palette() {
  static const std::vector<CityPaletteEntry> palette = {
      // Red-brown clay or concrete roof tiles, luminous reflectance about 0.1 (new
      // tile roofs 0.10–0.35: US EPA 2008, "Reducing Urban Heat Islands", Cool Roofs).
      {"RoofSurface", R"({"type": "diffuse", "reflectance": {"srgb": [0.45, 0.27, 0.2]}})"},
      // Brick or rendered masonry, reflectance about 0.25 (brick 0.2–0.4, ibid.).
      {"WallSurface", R"({"type": "diffuse", "reflectance": {"srgb": [0.6, 0.5, 0.42]}})"},
      {"GroundSurface", "concrete"},
      {"OuterCeilingSurface", "concrete"},
      {"OuterFloorSurface", "concrete"},
      {"ClosureSurface", "concrete"},
      {"Window", "glass"},
      // Painted timber, mid-brown.
      {"Door", R"({"type": "diffuse", "reflectance": {"srgb": [0.42, 0.3, 0.2]}})"},
      {"Road", "asphalt"},
      {"TransportSquare", "asphalt"},
      // Track ballast (crushed granite), reflectance about 0.15.
      {"Railway", R"({"type": "diffuse", "reflectance": 0.15})"},
      // Open water: the surface's Fresnel reflection (n = 1.333) over water's diffuse
      // volume reflectance of about 0.02 (Mobley 1994, "Light and Water", ch. 1),
      // ruffled by a light breeze.
      {"WaterBody", R"({"type": "layered", "reflectance": 0.02, "ior": 1.333, "roughness": 0.05})"},
      {"PlantCover", "grass"},
      {"SolitaryVegetationObject", "grass"},
      // Mixed land cover (soil, low vegetation, paving), reflectance about 0.17.
      {"LandUse", R"({"type": "diffuse", "reflectance": 0.17})"},
      {"TINRelief", R"({"type": "diffuse", "reflectance": 0.17})"},
      {"Bridge", "concrete"},
      {"Tunnel", "concrete"},
      {"default", "concrete"},
  };
  return palette;
}

namespace {

const CityPaletteEntry* find_entry(std::string_view key) {
  for (const CityPaletteEntry& e : default_city_palette())
    if (e.key == key) return &e;
  return nullptr;
}

}  // namespace

const CityPaletteEntry& city_palette_entry(const std::string& class_key) {
  if (const CityPaletteEntry* e = find_entry(class_key)) return *e;
  const size_t dot = class_key.find('.');
  if (dot != std::string::npos) {
    if (const CityPaletteEntry* e = find_entry(std::string_view(class_key).substr(dot + 1))) return *e;
    if (const CityPaletteEntry* e = find_entry(std::string_view(class_key).substr(0, dot))) return *e;
  }
  return *find_entry("default");
}

}  // namespace skylit
