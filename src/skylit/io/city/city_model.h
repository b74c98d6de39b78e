// A city model as a reader finds it in a file, before it is placed in the scene:
// city objects with their surfaces, in the file's own coordinate reference system.
// CityJSON (city/cityjson_reader) and CityGML (city/citygml_reader) both produce
// this; city/city_placement turns it into scene objects (coordinates transformed to
// the site's local east-north-up frame, polygons triangulated, semantic surfaces
// given their materials).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

// One planar polygon of a city object: its outer ring first, then its holes. Rings
// are not closed (the first point is not repeated). Coordinates are in the model's
// CRS, in double precision (survey coordinates need it), in the CRS's axis order
// as the file gives them (x, y, height).
struct CitySurface {
  std::vector<std::vector<Vec3>> rings;
  // The semantic class of the surface as the file names it ("RoofSurface",
  // "WallSurface", "GroundSurface", "Window", "Door", ...); empty when none.
  std::string semantic;
  // The appearance the file gives the surface in the chosen theme: an index into
  // CityModel::materials and one into CityModel::textures, or kNone.
  static constexpr int kNone = -1;
  int material = kNone;
  int texture = kNone;
  // With a texture: each ring's texture coordinates, one (s, t) per point, as the file
  // gives them (t up from the image's bottom row).
  std::vector<std::vector<std::array<float, 2>>> texture_coordinates;
};

// An appearance material as X3D defines it (CityGML app:X3DMaterial, CityJSON
// appearance.materials): colours in [0, 1].
struct CityMaterial {
  std::string name;
  std::array<double, 3> diffuse{0.8, 0.8, 0.8};
  std::array<double, 3> emissive{0, 0, 0};
  std::array<double, 3> specular{0, 0, 0};
  double shininess = 0.2;     // 0 to 1; the Phong exponent is 128 × shininess
  double transparency = 0.0;  // 0: opaque, 1: clear
  bool smooth = false;
};

// An image texture: its file (relative to the model's folder, as the file writes it) and
// how it repeats ("wrap", "mirror", "clamp", "border", "none"; empty when not given).
struct CityTexture {
  std::string image;
  std::string wrap_mode;
};

// One city object (a building, a part of one, a road, a TIN relief, ...).
struct CityObject {
  std::string id;
  // The object's type as CityJSON names it ("Building", "BuildingPart", "Road",
  // "TINRelief", "WaterBody", ...); a CityGML reader maps its feature classes to
  // these names (bldg:Building → "Building", tran:Road → "Road", dem:TINRelief →
  // "TINRelief", ...).
  std::string type;
  int lod = 0;  // the level of detail the surfaces were taken from (×10: LoD2.2 → 22)
  std::vector<CitySurface> surfaces;
};

struct CityModel {
  // The CRS as "EPSG:code" (e.g. "EPSG:7415"), or a PROJ-readable definition; empty
  // when the file names none (the scene must then say which).
  std::string crs;
  // The format writes easting first whatever the CRS's definition says (CityJSON: its
  // x is east, y north): reading a northing-first CRS's points the other way round is
  // then the format's rule, not a fault of the file's.
  bool easting_first = false;
  std::vector<CityObject> objects;
  // The appearances the surfaces refer to, and the themes: every theme the file has,
  // and the ones the surfaces' appearances were taken from (empty: none).
  std::vector<CityMaterial> materials;
  std::vector<CityTexture> textures;
  std::vector<std::string> appearance_themes;
  std::string material_theme, texture_theme;
};

// Which appearances a reader takes: none (the semantic palette alone), or those of one
// theme (empty: the first theme the file gives).
struct CityAppearanceOptions {
  bool read = true;
  std::string theme;
};

}  // namespace skylit
