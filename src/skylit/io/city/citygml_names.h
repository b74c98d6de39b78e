// The names CityGML (1.0 and 2.0) gives things, turned into the names a CityModel
// uses: feature classes into CityJSON's city-object types, boundary surfaces and
// openings into semantic surface classes, and a GML srsName into "EPSG:code".
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace skylit::citygml {

// The CityJSON type for a CityGML feature class's local name ("Building" →
// "Building", "Square" → "TransportSquare", "Track" → "Road", ...), or nullopt when
// the element is not a city object this reader keeps.
std::optional<std::string> city_object_type(std::string_view local_name);

// True for the features whose contents are inside a building and not part of its
// outer shell (Room, IntBuildingInstallation, BuildingFurniture): skipped.
bool is_interior_feature(std::string_view local_name);

// True for a thematic surface or opening whose name is the semantic class of the
// polygons inside it (RoofSurface, WallSurface, GroundSurface, Window, Door,
// TrafficArea, WaterSurface, ...).
bool is_semantic_surface(std::string_view local_name);
// The semantic class of such a surface as CityJSON names it: its own name, but 3.0's
// WindowSurface and DoorSurface are Window and Door.
std::string semantic_surface_class(std::string_view local_name);

// The level of detail a geometry property names, ×10 (lod2MultiSurface → 20,
// lod1Solid → 10, lod0FootPrint → 0), or nullopt for other names.
std::optional<int> lod_of_property(std::string_view local_name);

// "EPSG:code" (or "EPSG:horizontal+vertical" for a compound pair) for the srsName
// forms in use: "EPSG:6697", "urn:ogc:def:crs:EPSG::6697" (with or without a
// version), "urn:ogc:def:crs,crs:EPSG::28992,crs:EPSG::5709",
// "http(s)://www.opengis.net/def/crs/EPSG/0/6697" and
// "http://www.opengis.net/gml/srs/epsg.xml#6697", and the German AdV names
// ("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH" → "EPSG:25832+7837"). nullopt for
// anything else.
std::optional<std::string> epsg_from_srs_name(std::string_view srs_name);

}  // namespace skylit::citygml
