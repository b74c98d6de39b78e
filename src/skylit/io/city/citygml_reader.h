// Reading CityGML 2.0 and 1.0 files (OGC 12-019, 08-007r1) and the exterior of 3.0 ones
// (OGC 20-010; docs/citygml.md says what of it), including Japan's PLATEAU
// files with their i-UR extension (uro: elements are skipped; the city objects are
// plain CityGML): buildings and their parts (LoD0–LoD4, solids and boundary surfaces
// with their semantics, openings), roads, railways, squares, land use, vegetation,
// water bodies, TIN relief (dem:TINRelief triangles), generic city objects, bridges,
// tunnels and city furniture; appearances of one theme: X3D materials (app:X3DMaterial,
// given to polygons or surface aggregates by gml:id) and parameterized textures
// (app:ParameterizedTexture with app:TexCoordList, given to rings by gml:id).
//
// For each object the most detailed level of detail it has is kept (or the most
// detailed up to a chosen one). Surfaces that a
// solid references by xlink:href and a boundary surface defines (PLATEAU's lod2Solid)
// are taken once, with the boundary surface's semantic class. Implicit geometries
// (lodNImplicitRepresentation: a relative geometry, or a reference to an earlier one,
// through a 4 × 4 matrix to a reference point; trees, street furniture) are placed.
// Not read: interior features (rooms, furniture), gml:Tin control points, library
// objects of implicit geometries (external model files), georeferenced textures and
// texture coordinates made by app:TexCoordGen.
//
// Coordinates stay in the file's CRS and axis order. For EPSG:6697 (PLATEAU: JGD2011
// geographic + JGD2011 vertical height) that is latitude, longitude, height — the
// order the EPSG registry and PROJ define for it — with the height above the geoid
// (Tokyo Bay mean sea level, not the ellipsoid); the placement keeps it as the height
// above the local frame's origin.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "skylit/io/city/city_model.h"

namespace skylit {

struct CityGmlOptions {
  // The level of detail to take, ×10 (LoD2 → 20): each object's geometry of the
  // highest LoD not above it (objects with none are left out). Empty: each object's
  // most detailed geometry.
  std::optional<int> lod;
  CityAppearanceOptions appearance;
};

// Reads the file as it streams in (a tile of millions of triangles is never held as
// text). Throws InputError "<file>:<line>: <what>" for a file that is missing, not
// well-formed XML (truncated, ...), not a CityGML CityModel, names a CRS this reader
// cannot turn into an EPSG code or two different CRSs, has a ring without points, a
// polygon without an exterior ring, a coordinate that is not a finite
// number, a coordinate list whose length is not a multiple of its dimension, a
// reference (xlink:href="#id") to a surface that is not in the file, an X3D colour
// outside [0, 1], or texture coordinates (of the chosen theme) for a ring that is not
// in the file or not two per point.
CityModel read_citygml_file(const std::filesystem::path& file, const CityGmlOptions& options = {});

// The same from text in memory; `name` stands for the file in messages.
CityModel parse_citygml(std::string_view text, const std::string& name, const CityGmlOptions& options = {});

}  // namespace skylit
