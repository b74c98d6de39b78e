// CityGML's vocabulary, as listed in the OGC CityGML 2.0 standard (OGC 12-019) and the
// names 3.0 (OGC 20-010) changed, mapped onto CityJSON 2.0's city-object types (its
// specification, section 4).
#include "skylit/io/city/citygml_names.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <utility>
#include <vector>

namespace skylit::citygml {
namespace {

// CityGML feature class → CityJSON type. CityJSON has no Track or Square: a track
// is a road for rendering, a square is CityJSON's TransportSquare.
constexpr std::array<std::pair<std::string_view, std::string_view>, 18> kObjectTypes{{
    {"Building", "Building"},
    {"BuildingPart", "BuildingPart"},
    {"BuildingInstallation", "BuildingInstallation"},
    {"Road", "Road"},
    {"Railway", "Railway"},
    {"Track", "Road"},
    {"Square", "TransportSquare"},
    {"LandUse", "LandUse"},
    {"PlantCover", "PlantCover"},
    {"SolitaryVegetationObject", "SolitaryVegetationObject"},
    {"WaterBody", "WaterBody"},
    {"TINRelief", "TINRelief"},
    {"GenericCityObject", "GenericCityObject"},
    {"Bridge", "Bridge"},
    {"BridgePart", "BridgePart"},
    {"Tunnel", "Tunnel"},
    {"TunnelPart", "TunnelPart"},
    {"CityFurniture", "CityFurniture"},
}};

// CityGML 3.0 (OGC 20-010) keeps a building's inside in BuildingRoom (its boundaries the
// interior wall, floor and ceiling surfaces) and its furniture.
constexpr std::array<std::string_view, 8> kInteriorFeatures{"Room",
                                                            "IntBuildingInstallation",
                                                            "BuildingFurniture",
                                                            "IntBridgeInstallation",
                                                            "IntTunnelInstallation",
                                                            "BuildingRoom",
                                                            "BridgeRoom",
                                                            "HollowSpace"};

constexpr std::array<std::string_view, 16> kSemanticSurfaces{"RoofSurface",
                                                             "WallSurface",
                                                             "GroundSurface",
                                                             "ClosureSurface",
                                                             "OuterCeilingSurface",
                                                             "OuterFloorSurface",
                                                             "FloorSurface",
                                                             "CeilingSurface",
                                                             "InteriorWallSurface",
                                                             "Window",
                                                             "Door",
                                                             "TrafficArea",
                                                             "AuxiliaryTrafficArea",
                                                             "WaterSurface",
                                                             "WaterGroundSurface",
                                                             "WaterClosureSurface"};

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// The decimal code at the start of `s` (all of `s` must be digits), or nullopt.
std::optional<int> code_of(std::string_view s) {
  int code = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), code);
  if (ec != std::errc() || end != s.data() + s.size() || code <= 0) return std::nullopt;
  return code;
}

// "EPSG::6697", "EPSG:6.12:6697" or "EPSG:6697" (a URN's authority part): the code.
std::optional<int> urn_code(std::string_view part) {
  if (!starts_with(part, "EPSG:")) return std::nullopt;
  const auto last = part.rfind(':');
  return code_of(part.substr(last + 1));
}

// The German surveying authorities' (AdV) CRS names, used by every German state's
// CityGML: "urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH", horizontal then vertical.
constexpr std::array<std::pair<std::string_view, int>, 9> kAdvCrs{{
    {"ETRS89_UTM32", 25832},
    {"ETRS89_UTM33", 25833},
    {"DE_DHDN_3GK2", 31466},
    {"DE_DHDN_3GK3", 31467},
    {"DE_DHDN_3GK4", 31468},
    {"ETRS89_Lat-Lon", 4258},
    {"DE_DHHN92_NH", 5783},
    {"DE_DHHN2016_NH", 7837},
    {"DE_DHHN2016_NH_m", 7837},
}};

std::optional<int> adv_code(std::string_view name) {
  for (const auto& [n, code] : kAdvCrs)
    if (n == name) return code;
  return std::nullopt;
}

}  // namespace

std::optional<std::string> city_object_type(std::string_view local_name) {
  for (const auto& [name, type] : kObjectTypes)
    if (name == local_name) return std::string(type);
  return std::nullopt;
}

bool is_interior_feature(std::string_view local_name) {
  return std::find(kInteriorFeatures.begin(), kInteriorFeatures.end(), local_name) != kInteriorFeatures.end();
}

bool is_semantic_surface(std::string_view local_name) {
  return std::find(kSemanticSurfaces.begin(), kSemanticSurfaces.end(), local_name) != kSemanticSurfaces.end() ||
         local_name == "WindowSurface" || local_name == "DoorSurface";
}

std::string semantic_surface_class(std::string_view local_name) {
  // CityGML 3.0's fillings of an opening (con:WindowSurface, con:DoorSurface) are 2.0's
  // Window and Door, as CityJSON names them.
  if (local_name == "WindowSurface") return "Window";
  if (local_name == "DoorSurface") return "Door";
  return std::string(local_name);
}

std::optional<int> lod_of_property(std::string_view local_name) {
  // lod0FootPrint, lod1Solid, lod2MultiSurface, lod3Geometry, lod4MultiCurve, ...
  if (local_name.size() < 5 || !starts_with(local_name, "lod")) return std::nullopt;
  const char digit = local_name[3];
  if (digit < '0' || digit > '4') return std::nullopt;
  // Implicit geometries hold coordinates relative to a reference point: not read.
  if (local_name.find("Implicit") != std::string_view::npos) return std::nullopt;
  return (digit - '0') * 10;
}

std::optional<std::string> epsg_from_srs_name(std::string_view srs) {
  std::vector<int> codes;
  if (starts_with(srs, "urn:adv:crs:")) {
    std::string_view rest = srs.substr(12);
    while (!rest.empty()) {
      const auto star = rest.find('*');
      const auto c = adv_code(rest.substr(0, star));
      if (!c) return std::nullopt;
      codes.push_back(*c);
      rest = star == std::string_view::npos ? std::string_view{} : rest.substr(star + 1);
    }
  } else if (starts_with(srs, "EPSG:") || starts_with(srs, "epsg:")) {
    if (auto c = code_of(srs.substr(5))) codes.push_back(*c);
  } else if (starts_with(srs, "urn:ogc:def:crs,")) {
    // A compound of URNs: "urn:ogc:def:crs,crs:EPSG::28992,crs:EPSG::5709".
    std::string_view rest = srs.substr(16);
    while (!rest.empty()) {
      const auto comma = rest.find(',');
      std::string_view part = rest.substr(0, comma);
      if (!starts_with(part, "crs:")) return std::nullopt;
      const auto c = urn_code(part.substr(4));
      if (!c) return std::nullopt;
      codes.push_back(*c);
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    }
  } else if (starts_with(srs, "urn:ogc:def:crs:") || starts_with(srs, "urn:x-ogc:def:crs:")) {
    if (auto c = urn_code(srs.substr(srs.find(":crs:") + 5))) codes.push_back(*c);
  } else {
    for (std::string_view form : {"http://www.opengis.net/def/crs/EPSG/0/", "https://www.opengis.net/def/crs/EPSG/0/",
                                  "http://www.opengis.net/gml/srs/epsg.xml#"}) {
      if (starts_with(srs, form)) {
        if (auto c = code_of(srs.substr(form.size()))) codes.push_back(*c);
      }
    }
  }
  if (codes.empty() || codes.size() > 2) return std::nullopt;
  std::string out = "EPSG:" + std::to_string(codes[0]);
  if (codes.size() == 2) {
    out += '+';
    out += std::to_string(codes[1]);
  }
  return out;
}

}  // namespace skylit::citygml
