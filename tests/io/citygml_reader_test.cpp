// The CityGML reader: the PLATEAU sample (real data nobody on the project wrote), and
// small files written here for what the sample lacks (holes, TIN relief, X3D
// materials, GML 2 coordinates, CityGML 1.0) and for each malformed input.
#include "skylit/io/city/citygml_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../test_support.h"
#include "skylit/geometry/polygon_triangulation.h"
#include "skylit/io/city/city_placement.h"
#include "skylit/io/city/citygml_names.h"

namespace skylit {
namespace {

using skylit::testing::input_error_of;
using skylit::testing::TempDir;

const std::filesystem::path kPlateau = std::filesystem::path(SKYLIT_SOURCE_DIR) / ".." / "shared" / "data" / "models" /
                                       "plateau_53392642_bldg_6697_op2.gml";

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// How many gml:Polygon elements lie inside elements named `tag`, counted on the text
// (independently of the reader).
size_t polygons_inside(const std::string& text, const std::string& tag) {
  size_t count = 0;
  for (size_t at = text.find("<" + tag); at != std::string::npos; at = text.find("<" + tag, at + 1)) {
    const size_t end = text.find("</" + tag + ">", at);
    for (size_t p = text.find("<gml:Polygon", at); p < end; p = text.find("<gml:Polygon", p + 1)) ++count;
  }
  return count;
}

TEST(CityGmlReader, PlateauSampleHasEveryBuildingWithItsSemantics) {
  if (!std::filesystem::exists(kPlateau)) GTEST_SKIP() << "the shared PLATEAU sample is not here: " << kPlateau;
  const CityModel model = read_citygml_file(kPlateau);
  EXPECT_EQ(model.crs, "EPSG:6697");
  ASSERT_EQ(model.objects.size(), 8u);
  std::map<std::string, size_t> semantic_count;
  size_t textured = 0;
  for (const CityObject& o : model.objects) {
    EXPECT_EQ(o.type, "Building");
    EXPECT_EQ(o.id.substr(0, 4), "BLD_");
    EXPECT_EQ(o.lod, 20) << o.id;  // LoD2 boundary surfaces, not the LoD1 solid or the LoD0 roof edge
    std::map<std::string, size_t> mine;
    for (const CitySurface& s : o.surfaces) {
      ++mine[s.semantic];
      textured += s.texture != CitySurface::kNone;
    }
    EXPECT_GT(mine["RoofSurface"], 0u) << o.id;
    EXPECT_GT(mine["WallSurface"], 0u) << o.id;
    EXPECT_GT(mine["GroundSurface"], 0u) << o.id;
    EXPECT_EQ(mine[""], 0u) << o.id << ": the lod2Solid's references are the boundary surfaces' polygons";
    for (const auto& [k, n] : mine) semantic_count[k] += n;
  }
  // Each boundary surface's polygons once (the lod2Solid references them again).
  const std::string text = file_text(kPlateau);
  for (const std::string k : {"RoofSurface", "WallSurface", "GroundSurface", "OuterCeilingSurface"})
    EXPECT_EQ(semantic_count[k], polygons_inside(text, "bldg:" + k)) << k;
  EXPECT_GT(textured, 0u);  // the ParameterizedTextures' targets
}

TEST(CityGmlReader, PlateauCoordinatesAreTheFilesLatitudeLongitudeHeight) {
  if (!std::filesystem::exists(kPlateau)) GTEST_SKIP() << "the shared PLATEAU sample is not here: " << kPlateau;
  const CityModel model = read_citygml_file(kPlateau);
  // The first building's ground surface, read from the text by hand.
  const std::string text = file_text(kPlateau);
  const size_t ground = text.find("<bldg:GroundSurface");
  const size_t list = text.find("<gml:posList>", ground) + std::string("<gml:posList>").size();
  std::istringstream numbers(text.substr(list, text.find("</gml:posList>", list) - list));
  double lat = 0, lon = 0, h = 0;
  std::vector<Vec3> expected;
  while (numbers >> lat >> lon >> h) expected.emplace_back(lat, lon, h);
  expected.pop_back();  // the closing point
  const CitySurface* first_ground = nullptr;
  for (const CitySurface& s : model.objects[0].surfaces)
    if (s.semantic == "GroundSurface" && first_ground == nullptr) first_ground = &s;
  ASSERT_NE(first_ground, nullptr);
  ASSERT_EQ(first_ground->rings.size(), 1u);
  ASSERT_EQ(first_ground->rings[0].size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    // Both sides parse the same decimal text to the nearest double; 1e-9° is ~0.1 mm.
    EXPECT_NEAR(first_ground->rings[0][i].x, expected[i].x, 1e-9);
    EXPECT_NEAR(first_ground->rings[0][i].y, expected[i].y, 1e-9);
    EXPECT_NEAR(first_ground->rings[0][i].z, expected[i].z, 1e-9);
  }
  // Latitude first (EPSG:6697's axis order): Ota ward, Tokyo.
  EXPECT_NEAR(expected[0].x, 35.54, 0.01);
  EXPECT_NEAR(expected[0].y, 139.777, 0.01);
}

// A CityGML 2.0 file around the given members (EPSG:25832 via a URN).
std::string city_model(const std::string& members) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml"
 xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:dem="http://www.opengis.net/citygml/relief/2.0"
 xmlns:tran="http://www.opengis.net/citygml/transportation/2.0" xmlns:app="http://www.opengis.net/citygml/appearance/2.0"
 xmlns:xlink="http://www.w3.org/1999/xlink">
<gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::25832" srsDimension="3">
<gml:lowerCorner>0 0 0</gml:lowerCorner><gml:upperCorner>10 10 10</gml:upperCorner></gml:Envelope></gml:boundedBy>
)" + members +
         "\n</core:CityModel>\n";
}

// A 10 m × 8 m flat roof at 6 m with a 2 m × 3 m hole (a light well), an X3D
// material on it.
const std::string kHoledRoof = R"(<core:cityObjectMember><bldg:Building gml:id="b1">
<bldg:boundedBy><bldg:RoofSurface gml:id="r1"><bldg:lod2MultiSurface><gml:MultiSurface>
<gml:surfaceMember><gml:Polygon gml:id="roof">
<gml:exterior><gml:LinearRing><gml:posList>0 0 6 10 0 6 10 8 6 0 8 6 0 0 6</gml:posList></gml:LinearRing></gml:exterior>
<gml:interior><gml:LinearRing><gml:pos>4 2 6</gml:pos><gml:pos>4 5 6</gml:pos><gml:pos>6 5 6</gml:pos><gml:pos>6 2 6</gml:pos><gml:pos>4 2 6</gml:pos></gml:LinearRing></gml:interior>
</gml:Polygon></gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface></bldg:RoofSurface></bldg:boundedBy>
</bldg:Building></core:cityObjectMember>
<app:appearanceMember><app:Appearance><app:surfaceDataMember><app:X3DMaterial gml:id="red_tiles">
<app:diffuseColor>0.6 0.2 0.1</app:diffuseColor><app:target>#roof</app:target></app:X3DMaterial>
</app:surfaceDataMember></app:Appearance></app:appearanceMember>)";

double triangulated_area(const CitySurface& s) {
  double area = 0;
  std::vector<Vec3> points;
  for (const auto& ring : s.rings) points.insert(points.end(), ring.begin(), ring.end());
  for (const auto& t : triangulate_polygon_3d(s.rings)) {
    const Vec3 a = points[t[0]], b = points[t[1]], c = points[t[2]];
    const Vec3 u = b - a, v = c - a;
    area += 0.5 * std::sqrt(std::pow(u.y * v.z - u.z * v.y, 2) + std::pow(u.z * v.x - u.x * v.z, 2) +
                            std::pow(u.x * v.y - u.y * v.x, 2));
  }
  return area;
}

TEST(CityGmlReader, PolygonWithAHoleKeepsItsRingsAndMaterial) {
  const CityModel model = parse_citygml(city_model(kHoledRoof), "roof.gml");
  EXPECT_EQ(model.crs, "EPSG:25832");
  ASSERT_EQ(model.objects.size(), 1u);
  ASSERT_EQ(model.objects[0].surfaces.size(), 1u);
  const CitySurface& roof = model.objects[0].surfaces[0];
  EXPECT_EQ(roof.semantic, "RoofSurface");
  ASSERT_EQ(roof.rings.size(), 2u);
  EXPECT_EQ(roof.rings[0].size(), 4u);  // the closing point dropped
  EXPECT_EQ(roof.rings[1].size(), 4u);
  ASSERT_NE(roof.material, CitySurface::kNone);
  EXPECT_EQ(model.materials[static_cast<size_t>(roof.material)].name, "red_tiles");
  EXPECT_EQ(model.materials[static_cast<size_t>(roof.material)].diffuse, (std::array<double, 3>{0.6, 0.2, 0.1}));
  // Triangulated, the roof covers 80 − 6 = 74 m² (exact up to rounding: the corners
  // are integers).
  EXPECT_NEAR(triangulated_area(roof), 74.0, 1e-9);
}

TEST(CityGmlReader, TinReliefTrianglesAndRoadsAreRead) {
  const std::string members = R"(<core:cityObjectMember><dem:ReliefFeature gml:id="relief"><dem:lod>1</dem:lod>
<dem:reliefComponent><dem:TINRelief gml:id="tin"><dem:lod>2</dem:lod><dem:tin><gml:TriangulatedSurface gml:id="ts">
<gml:trianglePatches>
<gml:Triangle><gml:exterior><gml:LinearRing><gml:posList>0 0 1 10 0 2 0 10 3 0 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Triangle>
<gml:Triangle><gml:exterior><gml:LinearRing><gml:coordinates>10,0,2 10,10,4 0,10,3 10,0,2</gml:coordinates></gml:LinearRing></gml:exterior></gml:Triangle>
</gml:trianglePatches></gml:TriangulatedSurface></dem:tin></dem:TINRelief></dem:reliefComponent></dem:ReliefFeature></core:cityObjectMember>
<core:cityObjectMember><tran:Road gml:id="road"><tran:lod1MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon>
<gml:exterior><gml:LinearRing><gml:posList srsDimension="2">0 0 5 0 5 1 0 1</gml:posList></gml:LinearRing></gml:exterior>
</gml:Polygon></gml:surfaceMember></gml:MultiSurface></tran:lod1MultiSurface></tran:Road></core:cityObjectMember>)";
  const CityModel model = parse_citygml(city_model(members), "tin.gml");
  ASSERT_EQ(model.objects.size(), 2u);
  EXPECT_EQ(model.objects[0].type, "TINRelief");
  EXPECT_EQ(model.objects[0].lod, 20);
  ASSERT_EQ(model.objects[0].surfaces.size(), 2u);
  EXPECT_EQ(model.objects[0].surfaces[1].rings[0][1].z, 4.0);
  EXPECT_EQ(model.objects[1].type, "Road");
  EXPECT_EQ(model.objects[1].lod, 10);
  ASSERT_EQ(model.objects[1].surfaces.size(), 1u);
  EXPECT_EQ(model.objects[1].surfaces[0].rings[0].size(), 4u);
  EXPECT_EQ(model.objects[1].surfaces[0].rings[0][2].y, 1.0);
}

TEST(CityGmlReader, LandUseVegetationWaterAndGenericObjects) {
  const std::string square =
      "<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>"
      "0 0 0 1 0 0 1 1 0 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon>"
      "</gml:surfaceMember>";
  const std::string multi = "<gml:MultiSurface>" + square + "</gml:MultiSurface>";
  const std::string text =
      R"(<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml"
 xmlns:luse="http://www.opengis.net/citygml/landuse/2.0" xmlns:veg="http://www.opengis.net/citygml/vegetation/2.0"
 xmlns:wtr="http://www.opengis.net/citygml/waterbody/2.0" xmlns:gen="http://www.opengis.net/citygml/generics/2.0">)"
      "<core:cityObjectMember><luse:LandUse><luse:lod1MultiSurface>" +
      multi +
      "</luse:lod1MultiSurface></luse:LandUse></core:cityObjectMember>"
      "<core:cityObjectMember><veg:PlantCover><veg:lod2MultiSurface>" +
      multi +
      "</veg:lod2MultiSurface></veg:PlantCover></core:cityObjectMember>"
      "<core:cityObjectMember><veg:SolitaryVegetationObject><veg:lod2Geometry>" +
      multi +
      "</veg:lod2Geometry></veg:SolitaryVegetationObject></core:cityObjectMember>"
      "<core:cityObjectMember><wtr:WaterBody><wtr:boundedBy><wtr:WaterSurface><wtr:lod3Surface>"
      "<gml:CompositeSurface>" +
      square +
      "</gml:CompositeSurface></wtr:lod3Surface></wtr:WaterSurface>"
      "</wtr:boundedBy></wtr:WaterBody></core:cityObjectMember>"
      "<core:cityObjectMember><gen:GenericCityObject><gen:lod1Geometry>" +
      multi + "</gen:lod1Geometry></gen:GenericCityObject></core:cityObjectMember></core:CityModel>";
  const CityModel model = parse_citygml(text, "mixed.gml");
  ASSERT_EQ(model.objects.size(), 5u);
  const std::vector<std::pair<std::string, int>> expected{{"LandUse", 10},
                                                          {"PlantCover", 20},
                                                          {"SolitaryVegetationObject", 20},
                                                          {"WaterBody", 30},
                                                          {"GenericCityObject", 10}};
  for (size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(model.objects[k].type, expected[k].first);
    EXPECT_EQ(model.objects[k].lod, expected[k].second);
    ASSERT_EQ(model.objects[k].surfaces.size(), 1u) << expected[k].first;
    EXPECT_EQ(model.objects[k].surfaces[0].rings[0].size(), 3u);
  }
  EXPECT_EQ(model.objects[3].surfaces[0].semantic, "WaterSurface");
}

TEST(CityGmlReader, BuildingPartsAreObjectsOfTheirOwnAndReferencesResolve) {
  // CityGML 1.0; the LoD1 solid of the building, and a part whose LoD2 solid refers
  // forward to its wall; a LoD1 surface of the part is left out (LoD2 is kept).
  const std::string text =
      R"(<core:CityModel xmlns:core="http://www.opengis.net/citygml/1.0" xmlns:gml="http://www.opengis.net/gml"
 xmlns:bldg="http://www.opengis.net/citygml/building/1.0" xmlns:xlink="http://www.w3.org/1999/xlink">
<core:cityObjectMember><bldg:Building gml:id="b"><bldg:lod1Solid><gml:Solid srsName="EPSG:31256"><gml:exterior><gml:CompositeSurface>
<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 0 1 0 0 1 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
</gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod1Solid>
<bldg:consistsOfBuildingPart><bldg:BuildingPart gml:id="p">
<bldg:lod1MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 0 2 0 0 2 2 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface></bldg:lod1MultiSurface>
<bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface><gml:surfaceMember xlink:href="#w"/></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
<bldg:boundedBy><bldg:WallSurface><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon gml:id="w"><gml:exterior><gml:LinearRing><gml:posList>0 0 0 3 0 0 3 0 3 0 0 3</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface></bldg:WallSurface></bldg:boundedBy>
</bldg:BuildingPart></bldg:consistsOfBuildingPart></bldg:Building></core:cityObjectMember></core:CityModel>)";
  const CityModel model = parse_citygml(text, "parts.gml");
  EXPECT_EQ(model.crs, "EPSG:31256");
  // A room (interior, skipped) declaring a prefix of its own leaves nothing behind.
  std::string with_room = text;
  with_room.insert(
      with_room.find("<bldg:consistsOfBuildingPart>"),
      R"(<bldg:interiorRoom><bldg:Room xmlns:g="http://www.opengis.net/gml" srsDimension="2"><bldg:lod4Solid/></bldg:Room></bldg:interiorRoom>)");
  const CityModel roomed = parse_citygml(with_room, "room.gml");
  ASSERT_EQ(roomed.objects.size(), 2u);
  EXPECT_EQ(roomed.objects[0].surfaces.at(0).rings[0][1].x, 3.0);  // still read in 3-D
  ASSERT_EQ(model.objects.size(), 2u);
  // The part ends first.
  EXPECT_EQ(model.objects[0].id, "p");
  EXPECT_EQ(model.objects[0].type, "BuildingPart");
  EXPECT_EQ(model.objects[0].lod, 20);
  ASSERT_EQ(model.objects[0].surfaces.size(), 1u);
  EXPECT_EQ(model.objects[0].surfaces[0].semantic, "WallSurface");
  EXPECT_EQ(model.objects[0].surfaces[0].rings[0][1].x, 3.0);
  EXPECT_EQ(model.objects[1].id, "b");
  EXPECT_EQ(model.objects[1].lod, 10);
  ASSERT_EQ(model.objects[1].surfaces.size(), 1u);
  EXPECT_EQ(model.objects[1].surfaces[0].rings[0][1].x, 1.0);

  // Up to LoD1: the part's LoD1 surface instead of its wall; nothing is left at LoD0.
  const CityModel lod1 = parse_citygml(text, "parts.gml", {.lod = 10, .appearance = {}});
  ASSERT_EQ(lod1.objects.size(), 2u);
  EXPECT_EQ(lod1.objects[0].lod, 10);
  ASSERT_EQ(lod1.objects[0].surfaces.size(), 1u);
  EXPECT_EQ(lod1.objects[0].surfaces[0].rings[0][1].x, 2.0);
  EXPECT_TRUE(parse_citygml(text, "parts.gml", {.lod = 0, .appearance = {}}).objects.empty());
}

// The example scripts/make-citygml-example.py writes: a 6 × 6 cell TIN, four
// buildings (one with a courtyard: holes in its roof and ground) and a road.
TEST(CityGmlReader, ExampleCityBlockLoads) {
  const CityModel model =
      read_citygml_file(std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "models" / "city_block.gml");
  EXPECT_EQ(model.crs, "EPSG:6697");
  std::map<std::string, size_t> types;
  for (const CityObject& o : model.objects) ++types[o.type];
  EXPECT_EQ(types, (std::map<std::string, size_t>{{"Building", 4}, {"Road", 1}, {"TINRelief", 1}}));
  EXPECT_EQ(model.objects[0].surfaces.size(), 72u);  // 6 × 6 cells, two triangles each
  const CityObject& block = model.objects[4];
  EXPECT_EQ(block.id, "block");
  EXPECT_EQ(block.surfaces[0].semantic, "RoofSurface");
  EXPECT_EQ(block.surfaces[0].rings.size(), 2u);
  const int material = model.objects[1].surfaces[5].material;
  ASSERT_NE(material, CitySurface::kNone);
  EXPECT_EQ(model.materials[static_cast<size_t>(material)].name, "red_tiles");
}

TEST(CityGmlReader, AReferenceMayNameAWholeMultiSurface) {
  // The LoD2 solid names the roof's multi-surface (two polygons) by its id.
  const std::string members =
      R"(<core:cityObjectMember><bldg:Building gml:id="b"><bldg:lod2Solid><gml:Solid><gml:exterior>
<gml:CompositeSurface><gml:surfaceMember xlink:href="#roofs"/></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
<bldg:boundedBy><bldg:RoofSurface><bldg:lod2MultiSurface><gml:MultiSurface gml:id="roofs">
<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 5 4 0 5 4 4 7</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 5 4 4 7 0 4 7</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
</gml:MultiSurface></bldg:lod2MultiSurface></bldg:RoofSurface></bldg:boundedBy></bldg:Building></core:cityObjectMember>)";
  const CityModel model = parse_citygml(city_model(members), "ref.gml");
  ASSERT_EQ(model.objects.size(), 1u);
  ASSERT_EQ(model.objects[0].surfaces.size(), 2u);  // each once
  for (const CitySurface& s : model.objects[0].surfaces) EXPECT_EQ(s.semantic, "RoofSurface");
}

// A gml:Surface of gml:PolygonPatch elements (GML 3.1.1 §10.5.10), as some exporters
// write a roof: read as its polygons, with a hole, and named whole by a reference from
// the solid (the building had vanished, and the reference named "no surface").
TEST(CityGmlReader, ASurfaceOfPolygonPatchesIsItsPolygons) {
  const std::string members =
      R"(<core:cityObjectMember><bldg:Building gml:id="b"><bldg:lod2Solid><gml:Solid><gml:exterior>
<gml:CompositeSurface><gml:surfaceMember xlink:href="#roof"/></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
<bldg:boundedBy><bldg:RoofSurface><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember>
<gml:Surface gml:id="roof"><gml:patches>
<gml:PolygonPatch><gml:exterior><gml:LinearRing><gml:posList>0 0 6 10 0 6 10 8 6 0 8 6 0 0 6</gml:posList></gml:LinearRing></gml:exterior>
<gml:interior><gml:LinearRing><gml:posList>4 2 6 4 5 6 6 5 6 6 2 6 4 2 6</gml:posList></gml:LinearRing></gml:interior></gml:PolygonPatch>
<gml:PolygonPatch><gml:exterior><gml:LinearRing><gml:posList>10 0 6 12 0 6 12 8 6 10 8 6 10 0 6</gml:posList></gml:LinearRing></gml:exterior></gml:PolygonPatch>
</gml:patches></gml:Surface></gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface></bldg:RoofSurface></bldg:boundedBy>
</bldg:Building></core:cityObjectMember>)";
  const CityModel model = parse_citygml(city_model(members), "patches.gml");
  ASSERT_EQ(model.objects.size(), 1u);
  ASSERT_EQ(model.objects[0].surfaces.size(), 2u);  // each patch once
  double area = 0;
  for (const CitySurface& s : model.objects[0].surfaces) {
    EXPECT_EQ(s.semantic, "RoofSurface");
    area += triangulated_area(s);
  }
  EXPECT_NEAR(area, 74.0 + 16.0, 1e-9);
}

// CityGML 3.0 (OGC 20-010): thematic surfaces are core:boundary members in the
// construction module, a window is a con:WindowSurface filling a wall's opening, and the
// inside is a bldg:BuildingRoom. The window reads as the 2.0 Window; the room's interior
// wall is not drawn (it had been, and the window lost).
TEST(CityGmlReader, CityGml3WindowsAreWindowsAndRoomsStayInside) {
  const std::string model = R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/3.0" xmlns:gml="http://www.opengis.net/gml/3.2"
 xmlns:bldg="http://www.opengis.net/citygml/building/3.0" xmlns:con="http://www.opengis.net/citygml/construction/3.0">
<gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::25832" srsDimension="3">
<gml:lowerCorner>0 0 0</gml:lowerCorner><gml:upperCorner>10 10 10</gml:upperCorner></gml:Envelope></gml:boundedBy>
<core:cityObjectMember><bldg:Building gml:id="b">
<core:boundary><con:WallSurface gml:id="w"><core:lod3MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon>
<gml:exterior><gml:LinearRing><gml:posList>0 0 0 10 0 0 10 0 3 0 0 3 0 0 0</gml:posList></gml:LinearRing></gml:exterior>
<gml:interior><gml:LinearRing><gml:posList>4 0 1 4 0 2 6 0 2 6 0 1 4 0 1</gml:posList></gml:LinearRing></gml:interior>
</gml:Polygon></gml:surfaceMember></gml:MultiSurface></core:lod3MultiSurface>
<con:fillingSurface><con:WindowSurface gml:id="win"><core:lod3MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon>
<gml:exterior><gml:LinearRing><gml:posList>4 0 1 6 0 1 6 0 2 4 0 2 4 0 1</gml:posList></gml:LinearRing></gml:exterior>
</gml:Polygon></gml:surfaceMember></gml:MultiSurface></core:lod3MultiSurface></con:WindowSurface></con:fillingSurface>
</con:WallSurface></core:boundary>
<bldg:buildingRoom><bldg:BuildingRoom><core:boundary><con:InteriorWallSurface><core:lod3MultiSurface><gml:MultiSurface>
<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0.2 0 0 0.2 3 10 0.2 3 10 0.2 0 0 0.2 0</gml:posList>
</gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface></core:lod3MultiSurface>
</con:InteriorWallSurface></core:boundary></bldg:BuildingRoom></bldg:buildingRoom>
</bldg:Building></core:cityObjectMember></core:CityModel>)";
  const CityModel parsed = parse_citygml(model, "v3.gml");
  ASSERT_EQ(parsed.objects.size(), 1u);
  std::vector<std::string> semantics;
  for (const CitySurface& surface : parsed.objects[0].surfaces) semantics.push_back(surface.semantic);
  EXPECT_EQ(semantics, (std::vector<std::string>{"WallSurface", "Window"}));
}

// A ring of two distinct points encloses nothing (the OGC's Lyon sample has one, and
// the whole file was refused for it): as an exterior, its polygon is kept and the
// placement skips it as a surface of zero area; as a hole, it is dropped.
TEST(CityGmlReader, RingsOfTwoPointsEncloseNothingAndStopNothing) {
  std::string two_point_hole = kHoledRoof, two_point_roof = kHoledRoof;
  two_point_hole.replace(two_point_hole.find("<gml:pos>6 5 6</gml:pos><gml:pos>6 2 6</gml:pos>"), 48, "");
  const CityModel holed = parse_citygml(city_model(two_point_hole), "hole.gml");
  ASSERT_EQ(holed.objects.at(0).surfaces.size(), 1u);
  EXPECT_EQ(holed.objects[0].surfaces[0].rings.size(), 1u);  // the hole dropped
  EXPECT_NEAR(triangulated_area(holed.objects[0].surfaces[0]), 80.0, 1e-9);

  // A texture's coordinates for the dropped hole are skipped with it.
  std::string textured = two_point_hole;
  textured.replace(textured.find("<gml:interior><gml:LinearRing>"), 30,
                   R"(<gml:interior><gml:LinearRing gml:id="well">)");
  textured += R"(<app:appearanceMember><app:Appearance><app:surfaceDataMember><app:ParameterizedTexture>
<app:imageURI>roof.png</app:imageURI><app:target uri="#roof"><app:TexCoordList>
<app:textureCoordinates ring="#well">0 0 1 0 0 0</app:textureCoordinates>
</app:TexCoordList></app:target></app:ParameterizedTexture></app:surfaceDataMember></app:Appearance></app:appearanceMember>)";
  EXPECT_EQ(parse_citygml(city_model(textured), "hole.gml").objects.at(0).surfaces.at(0).rings.size(), 1u);

  two_point_roof.replace(two_point_roof.find("0 0 6 10 0 6 10 8 6 0 8 6 0 0 6"), 31, "0 0 6 10 0 6 0 0 6");
  const CityModel flat = parse_citygml(city_model(two_point_roof), "roof.gml");
  ASSERT_EQ(flat.objects.at(0).surfaces.size(), 1u);
  EXPECT_EQ(flat.objects[0].surfaces[0].rings[0].size(), 2u);
  EXPECT_EQ(place_city_model(flat, {}, "roof.gml").degenerate_surfaces, 1u);
}

// Two trees from one library shape: the first defines its relative geometry (a
// triangle) with a matrix that doubles x and turns nothing else; the second refers to it
// and has no matrix (the identity). p' = M p + reference point.
TEST(CityGmlReader, ImplicitGeometriesArePlacedAtTheirReferencePoints) {
  const auto tree = [](const std::string& id, const std::string& geometry, const std::string& matrix,
                       const std::string& point) {
    return "<core:cityObjectMember><veg:SolitaryVegetationObject gml:id=\"" + id +
           "\"><veg:lod2ImplicitRepresentation><core:ImplicitGeometry>" + matrix + geometry +
           "<core:referencePoint><gml:Point srsName=\"EPSG:28992\"><gml:pos>" + point +
           "</gml:pos></gml:Point></core:referencePoint></core:ImplicitGeometry></veg:lod2ImplicitRepresentation>"
           "</veg:SolitaryVegetationObject></core:cityObjectMember>\n";
  };
  const std::string head = R"(<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0"
 xmlns:veg="http://www.opengis.net/citygml/vegetation/2.0" xmlns:gml="http://www.opengis.net/gml"
 xmlns:xlink="http://www.w3.org/1999/xlink">
)";
  const std::string shape =
      "<core:relativeGMLGeometry><gml:MultiSurface gml:id=\"crown\"><gml:surfaceMember><gml:Polygon><gml:exterior>"
      "<gml:LinearRing><gml:posList>0 0 0 1 0 0 0 1 2 0 0 0</gml:posList></gml:LinearRing></gml:exterior>"
      "</gml:Polygon></gml:surfaceMember></gml:MultiSurface></core:relativeGMLGeometry>";
  const std::string doubled = "<core:transformationMatrix>2 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</core:transformationMatrix>";
  const std::string text = head + tree("t1", shape, doubled, "100 200 5") +
                           tree("t2", "<core:relativeGMLGeometry xlink:href=\"#crown\"/>", "", "110 200 5") +
                           "</core:CityModel>\n";
  const CityModel model = parse_citygml(text, "trees.gml");
  EXPECT_EQ(model.crs, "EPSG:28992");
  ASSERT_EQ(model.objects.size(), 2u);
  EXPECT_EQ(model.objects[0].lod, 20);
  ASSERT_EQ(model.objects[0].surfaces.size(), 1u);
  ASSERT_EQ(model.objects[1].surfaces.size(), 1u);
  const auto& first = model.objects[0].surfaces[0].rings[0];
  EXPECT_EQ(first[1], (Vec3{102, 200, 5}));  // (1, 0, 0) doubled in x, moved
  EXPECT_EQ(first[2], (Vec3{100, 201, 7}));
  const auto& second = model.objects[1].surfaces[0].rings[0];
  EXPECT_EQ(second[1], (Vec3{111, 200, 5}));  // the library shape as read, not the first tree's
  EXPECT_EQ(second[2], (Vec3{110, 201, 7}));
  // A reference to nothing before it is one located error.
  const std::string dangling =
      head + tree("t3", "<core:relativeGMLGeometry xlink:href=\"#nothing\"/>", "", "0 0 0") + "</core:CityModel>\n";
  EXPECT_EQ(testing::input_error_of([&] { parse_citygml(dangling, "trees.gml"); }),
            "trees.gml:4: core:relativeGMLGeometry xlink:href='#nothing' names no implicit geometry before it");
}

// Parts the reader leaves out do not stop the file: a reference to a room's wall (a
// CityGML 3.0 storey names its rooms' surfaces, the OGC's BuildingUnits sample) is left
// out with the room, and an address's location in another CRS (EPSG:4326 in the OGC's
// 3.0 samples) is not read. A reference to nothing at all stays an error (above).
TEST(CityGmlReader, ReferencesIntoRoomsAndAddressesInAnotherCrsDoNotStopTheFile) {
  const std::string room = R"(<bldg:interiorRoom><bldg:Room gml:id="room1"><bldg:lod4Solid><gml:Solid><gml:exterior>
<gml:CompositeSurface><gml:surfaceMember><gml:Polygon gml:id="room_wall"><gml:exterior><gml:LinearRing>
<gml:posList>0 0 0 1 0 0 1 0 1 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
</gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod4Solid></bldg:Room></bldg:interiorRoom>)";
  const std::string address = R"(<bldg:address><core:Address><core:multiPoint><gml:MultiPoint srsName="EPSG:4326">
<gml:pointMember><gml:Point><gml:pos>48.1 11.5 0</gml:pos></gml:Point></gml:pointMember></gml:MultiPoint>
</core:multiPoint></core:Address></bldg:address>)";
  const std::string storey_reference = R"(<bldg:lod2MultiSurface><gml:MultiSurface>
<gml:surfaceMember xlink:href="#room_wall"/></gml:MultiSurface></bldg:lod2MultiSurface>)";
  std::string members = kHoledRoof;
  members.replace(members.find("</bldg:Building>"), 0, room + address + storey_reference);
  const CityModel model = parse_citygml(city_model(members), "rooms.gml");
  EXPECT_EQ(model.crs, "EPSG:25832");
  ASSERT_EQ(model.objects.size(), 1u);
  ASSERT_EQ(model.objects[0].surfaces.size(), 1u);  // the roof alone
  EXPECT_EQ(model.objects[0].surfaces[0].rings[0][1], (Vec3{10, 0, 6}));
}

TEST(CityGmlReader, SrsNamesInTheirCommonForms) {
  EXPECT_EQ(citygml::epsg_from_srs_name("http://www.opengis.net/def/crs/EPSG/0/6697"), "EPSG:6697");
  EXPECT_EQ(citygml::epsg_from_srs_name("https://www.opengis.net/def/crs/EPSG/0/7415"), "EPSG:7415");
  EXPECT_EQ(citygml::epsg_from_srs_name("urn:ogc:def:crs:EPSG:6.12:2056"), "EPSG:2056");
  EXPECT_EQ(citygml::epsg_from_srs_name("urn:ogc:def:crs,crs:EPSG::28992,crs:EPSG::5709"), "EPSG:28992+5709");
  EXPECT_EQ(citygml::epsg_from_srs_name("http://www.opengis.net/gml/srs/epsg.xml#4326"), "EPSG:4326");
  EXPECT_EQ(citygml::epsg_from_srs_name("EPSG:6677"), "EPSG:6677");
  EXPECT_EQ(citygml::epsg_from_srs_name("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH"), "EPSG:25832+7837");
  EXPECT_EQ(citygml::epsg_from_srs_name("urn:adv:crs:ETRS89_UTM33"), "EPSG:25833");
  EXPECT_FALSE(citygml::epsg_from_srs_name("urn:adv:crs:ETRS89_UTM99"));
  EXPECT_FALSE(citygml::epsg_from_srs_name("Local"));
  EXPECT_FALSE(citygml::epsg_from_srs_name("EPSG:abc"));
  EXPECT_FALSE(citygml::epsg_from_srs_name("http://www.opengis.net/def/crs/EPSG/0/"));
}

// Each malformed input gives one InputError naming the file and the line.
TEST(CityGmlReader, MalformedFilesNameTheFileAndLine) {
  const std::string good = city_model(kHoledRoof);
  // Truncated in the middle of the roof.
  EXPECT_EQ(
      input_error_of([&] { parse_citygml(good.substr(0, good.find("<gml:interior>") + 20), "t.gml"); }).substr(0, 6),
      "t.gml:");
  const auto message_for = [&](const std::string& from, const std::string& to) {
    std::string bad = good;
    bad.replace(bad.find(from), from.size(), to);
    return input_error_of([&] { parse_citygml(bad, "bad.gml"); });
  };
  EXPECT_EQ(message_for("urn:ogc:def:crs:EPSG::25832", "Local"),
            "bad.gml:6: srsName 'Local' is not a coordinate reference system this reader knows (EPSG:n, "
            "urn:ogc:def:crs:EPSG::n, http://www.opengis.net/def/crs/EPSG/0/n)");
  EXPECT_EQ(message_for("0 0 6 10 0 6 10 8 6 0 8 6 0 0 6", ""), "bad.gml:11: a ring (gml:LinearRing) without points");
  EXPECT_EQ(message_for("10 8 6 0 8 6", "10 8 6 0 8x 6"),
            "bad.gml:11: expected a coordinate (a finite number), found '8x'");
  EXPECT_EQ(message_for("10 8 6 0 8 6", "10 8 6 0 nan 6"),
            "bad.gml:11: expected a coordinate (a finite number), found 'nan'");
  EXPECT_EQ(message_for("10 8 6 0 8 6", "10 8 6 0 8"), "bad.gml:11: 14 coordinates are not points of dimension 3");
  EXPECT_EQ(message_for("<gml:pos>4 5 6</gml:pos>", "<gml:pos>4 5 6 7</gml:pos>"),
            "bad.gml:12: a gml:pos has 4 coordinates, not 2 or 3");
  EXPECT_EQ(message_for("core:CityModel xmlns", "core:CityMode xmlns").substr(0, 10), "bad.gml:2:");
  const std::string dangling = R"(<core:cityObjectMember><bldg:Building><bldg:lod2Solid><gml:Solid><gml:exterior>
<gml:CompositeSurface><gml:surfaceMember xlink:href="#nowhere"/></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
</bldg:Building></core:cityObjectMember>)";
  EXPECT_EQ(input_error_of([&] { parse_citygml(city_model(dangling), "d.gml"); }),
            "d.gml:9: xlink:href '#nowhere' names no surface in the file");
  EXPECT_EQ(input_error_of([&] { read_citygml_file("/nonexistent/x.gml"); }).substr(0, 18), "/nonexistent/x.gml");
}

}  // namespace
}  // namespace skylit
