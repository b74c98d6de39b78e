// A city model (city_model.h, in its file's CRS) placed in the scene: every point
// transformed by PROJ to WGS 84 latitude, longitude and height, then to the scene's
// local east-north-up frame (metres, x east, y TRUE north, z up) around an origin on
// the earth; surfaces triangulated, each triangle labelled with its class
// ("Building.RoofSurface", "Road", ...) for the materials (io/scene/city_reader.cpp).
// Both city readers (CityJSON, CityGML) end here; so does terrain that must share the
// frame (geo_frame.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "skylit/geometry/triangle_mesh.h"
#include "skylit/io/city/city_model.h"
#include "skylit/io/city/geo_frame.h"

namespace skylit {

// Which part of a large model to take: the objects whose centre (the mean of their
// vertices) lies within `radius_m` of a point, or within a box of longitudes and
// latitudes.
struct CityRegion {
  std::optional<std::array<double, 2>> center_lonlat_deg;  // with radius_m
  double radius_m = 0;
  std::optional<std::array<double, 4>> bbox_lonlat_deg;  // west, south, east, north
};

// The earth's curvature and the atmosphere's refraction for long views: a point at
// horizontal distance d from the origin is lowered by d²/(2R)·(1 − k) (geo_frame.h).
enum class EarthCurvature {
  off,
  on,
  // On when any vertex lies more than kCurvatureAutoDistanceM from the origin.
  automatic,
};
// At 1 km the drop is 6.8 cm (k = 0.13): about what a city model's heights are known to.
inline constexpr double kCurvatureAutoDistanceM = 1000.0;

struct CityPlacementOptions {
  // The CRS of the model's coordinates when the file names none or names it wrongly
  // ("EPSG:7415", a PROJ string, ...); empty: the model's own.
  std::string crs;
  // The scene's origin (its `site`); empty: the model's centre, which the caller then
  // takes as the site for the sun's position.
  std::optional<GeoPoint> origin;
  std::optional<CityRegion> region;
  EarthCurvature curvature = EarthCurvature::automatic;
  double refraction_k = kStandardRefractionK;
  // The height (metres, as the CRS gives heights) that becomes z = 0; empty: the
  // median of the objects' lowest points. A DEM placed beside a city model takes the
  // model's, so that both share one vertical frame.
  std::optional<double> ground_height_m;
};

struct PlacedCityObject {
  std::string id;
  std::string type;  // as in CityObject
  int lod = 0;
  TriangleMesh mesh;  // metres in the local frame
  // Per triangle: its class, an index into PlacedCity::classes.
  std::vector<uint32_t> triangle_class;
  // Per triangle, when the model has appearances (else empty): its surface's appearance
  // material and texture (indices into CityModel::materials and ::textures, or
  // CitySurface::kNone), and its corners' texture coordinates (u across the image, v
  // down from its top row as Texture reads them; zero without a texture).
  std::vector<int32_t> triangle_material, triangle_texture;
  std::vector<CornerUvs> corner_uvs;
};

struct PlacedCity {
  std::string crs;  // the CRS that was used
  // The local frame's origin; its height is the model's ground level (the median of
  // the objects' lowest points), which becomes z = 0.
  GeoPoint origin;
  bool origin_from_model = false;  // the model's centre (no site given)
  bool curvature_applied = false;
  // The file's first two coordinates read the other way round than the CRS defines them
  // (CrsToWgs84::fit_axis_order): only so do they lie in the CRS's area of use.
  bool axes_swapped = false;
  // ... and the format writes them so (CityModel::easting_first): nothing to warn of.
  bool axes_swapped_by_format = false;
  // "Type.Semantic" ("Building.RoofSurface") or "Type" for surfaces without one. A
  // building's surfaces without semantics are classed by their facing (roof: facing
  // up, ground: facing down, wall: otherwise) so that LoD1 blocks get roofs too.
  std::vector<std::string> classes;
  std::vector<PlacedCityObject> objects;
  size_t objects_outside_region = 0;
  size_t degenerate_surfaces = 0;  // surfaces that gave no triangle (zero area)
};

// Places the model; `source` names the file in messages. Throws InputError for a CRS
// PROJ does not know or cannot transform, or coordinates it cannot transform.
PlacedCity place_city_model(const CityModel& model, const CityPlacementOptions& options, const std::string& source);

}  // namespace skylit
