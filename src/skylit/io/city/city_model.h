// A city model as a reader finds it in a file, before it is placed in the scene:
// city objects with their surfaces, in the file's own coordinate reference system.
// CityJSON (city/cityjson_reader) and CityGML (city/citygml_reader) both produce
// this; city/city_placement turns it into scene objects (coordinates transformed to
// the site's local east-north-up frame, polygons triangulated, semantic surfaces
// given their materials).
#pragma once

#include <optional>
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
  // A material the file's appearance gives the surface (its name), if any.
  std::optional<std::string> appearance_material;
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
  std::vector<CityObject> objects;
};

}  // namespace skylit
