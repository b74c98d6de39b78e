// The CityJSON reader (io/city/cityjson_reader.h): the real samples load whole, each
// geometry kind and the LoD choice read as the specification says, rings of one or two
// points tolerated as CityGML's are, and malformed files give one located error.
#include "skylit/io/city/cityjson_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "../../test_support.h"
#include "skylit/io/city/city_placement.h"

namespace skylit {
namespace {

const std::filesystem::path kModels = std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/models";

// The ids of the file's objects of a type, counted straight from the JSON.
std::set<std::string> ids_of_type(const std::filesystem::path& file, const std::string& type) {
  const auto document = nlohmann::json::parse(testing::read_file(file));
  std::set<std::string> ids;
  for (const auto& [id, object] : document["CityObjects"].items())
    if (object["type"] == type) ids.insert(id);
  return ids;
}

TEST(CityJsonReader, RealSamplesLoadEveryBuildingWithItsSurfaces) {
  for (const char* name : {"delft.city.json", "rotterdam_one.city.json"}) {
    const auto file = kModels / name;
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared models";
    const CityModel model = read_cityjson_file(file);
    EXPECT_EQ(model.crs, "EPSG:7415") << name;
    const std::set<std::string> buildings = ids_of_type(file, "Building");
    ASSERT_FALSE(buildings.empty());
    std::set<std::string> read;
    for (const CityObject& o : model.objects)
      if (o.type == "Building") {
        read.insert(o.id);
        EXPECT_FALSE(o.surfaces.empty()) << name << " " << o.id;
      }
    EXPECT_EQ(read, buildings) << name;
  }
}

TEST(CityJsonReader, RotterdamSemanticSurfacesAndQuantisedVertices) {
  const auto file = kModels / "rotterdam_one.city.json";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared models";
  const CityModel model = read_cityjson_file(file);
  ASSERT_EQ(model.objects.size(), 1u);
  std::map<std::string, int> semantics;
  for (const CitySurface& s : model.objects[0].surfaces) ++semantics[s.semantic];
  EXPECT_GT(semantics["RoofSurface"], 0);
  EXPECT_GT(semantics["WallSurface"], 0);
  EXPECT_EQ(semantics["GroundSurface"], 1);
  EXPECT_EQ(model.objects[0].lod, 20);
  // Vertex 0 is [523948, 209058, 15311] × 0.001 + (90409.32, 435440.44, 0).
  bool found = false;
  for (const CitySurface& s : model.objects[0].surfaces)
    for (const auto& ring : s.rings)
      for (const Vec3& p : ring) found |= length(p - Vec3{90933.358, 435649.498, 15.311}) < 1e-6;
  EXPECT_TRUE(found);
}

// A small file with every geometry kind: a Solid with semantics and a material, a
// MultiSolid, a MultiSurface at two LoDs and an instance of a template.
constexpr const char* kSmall = R"({
  "type": "CityJSON", "version": "2.0",
  "transform": {"scale": [0.01, 0.01, 0.01], "translate": [1000, 2000, 0]},
  "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/28992"},
  "appearance": {"materials": [{"name": "red brick", "diffuseColor": [0.6, 0.2, 0.1]}]},
  "vertices": [[0, 0, 0], [100, 0, 0], [100, 100, 0], [0, 100, 0], [0, 0, 100], [100, 0, 100],
               [100, 100, 100], [0, 100, 100]],
  "geometry-templates": {"templates": [{"type": "MultiSurface", "lod": "2",
                                         "boundaries": [[[0, 1, 2]]]}],
                         "vertices-templates": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
  "CityObjects": {
    "house": {"type": "Building", "geometry": [{"type": "Solid", "lod": "1.2",
      "boundaries": [[[[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]]]],
      "semantics": {"surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface"}, {"type": "WallSurface"}],
                    "values": [[0, 1, 2, 2, 2, null]]},
      "material": {"default": {"values": [[null, null, 0, 0, 0, 0]]}}}]},
    "pair": {"type": "BuildingPart", "geometry": [{"type": "MultiSolid", "lod": "1",
      "boundaries": [[[[[0, 1, 2]]]], [[[[4, 5, 6]], [[4, 6, 7]]]]]}]},
    "lawn": {"type": "PlantCover", "geometry": [
      {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2, 3]]]},
      {"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 2, 3]], [[4, 5, 6, 7]]]}]},
    "tree": {"type": "SolitaryVegetationObject", "geometry": [{"type": "GeometryInstance", "template": 0,
      "boundaries": [6], "transformationMatrix": [2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]}
  }
})";

const CityObject& object(const CityModel& model, const std::string& id) {
  for (const CityObject& o : model.objects)
    if (o.id == id) return o;
  throw std::runtime_error("no object " + id);
}

TEST(CityJsonReader, EveryGeometryKindAndTheLodChoice) {
  const CityModel model = read_cityjson_text(kSmall, "small.city.json");
  EXPECT_EQ(model.crs, "EPSG:28992");
  const CityObject& house = object(model, "house");
  ASSERT_EQ(house.surfaces.size(), 6u);
  EXPECT_EQ(house.lod, 12);
  EXPECT_EQ(house.surfaces[0].semantic, "GroundSurface");
  EXPECT_EQ(house.surfaces[1].semantic, "RoofSurface");
  EXPECT_EQ(house.surfaces[5].semantic, "");
  EXPECT_EQ(house.surfaces[1].material, CitySurface::kNone);
  ASSERT_EQ(house.surfaces[2].material, 0);
  EXPECT_EQ(model.materials[0].name, "red brick");
  EXPECT_EQ(model.materials[0].diffuse, (std::array<double, 3>{0.6, 0.2, 0.1}));
  // Quantised: index 6 is (100, 100, 100) × 0.01 + (1000, 2000, 0).
  EXPECT_EQ(house.surfaces[1].rings[0][2], (Vec3{1001, 2001, 1}));
  EXPECT_EQ(object(model, "pair").surfaces.size(), 3u);
  // The most detailed LoD by default; the one asked for (or the best below it).
  EXPECT_EQ(object(model, "lawn").surfaces.size(), 2u);
  CityJsonOptions lod1;
  lod1.lod = 10;
  const CityModel at_lod1 = read_cityjson_text(kSmall, "small.city.json", lod1);
  EXPECT_EQ(object(at_lod1, "lawn").surfaces.size(), 1u);
  EXPECT_TRUE(object(at_lod1, "house").surfaces.empty());  // LoD1.2 is above LoD1
  // The instance: template points scaled by (2, 3, 1), moved to vertex 6.
  const auto& tree = object(model, "tree").surfaces;
  ASSERT_EQ(tree.size(), 1u);
  EXPECT_EQ(tree[0].rings[0][1], (Vec3{1003, 2001, 1}));
  EXPECT_EQ(tree[0].rings[0][2], (Vec3{1001, 2004, 1}));
}

TEST(CityJsonReader, CityJsonSeqFeaturesUseTheHeadersTransform) {
  const std::string text =
      R"({"type": "CityJSON", "version": "2.0", "transform": {"scale": [0.5, 0.5, 1], "translate": [10, 20, 0]},)"
      R"( "metadata": {"referenceSystem": "EPSG:7415"}, "CityObjects": {}, "vertices": []})"
      "\n"
      R"({"type": "CityJSONFeature", "id": "a", "CityObjects": {"a": {"type": "Building", "geometry": [)"
      R"({"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}]}}, "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]]})"
      "\n"
      R"({"type": "CityJSONFeature", "id": "b", "CityObjects": {"b": {"type": "Road", "geometry": [)"
      R"({"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}]}}, "vertices": [[4, 4, 0], [6, 4, 0], [4, 6, 0]]})"
      "\n";
  const CityModel model = read_cityjson_text(text, "town.city.jsonl");
  EXPECT_EQ(model.crs, "EPSG:7415");
  ASSERT_EQ(model.objects.size(), 2u);
  EXPECT_EQ(model.objects[1].surfaces[0].rings[0][1], (Vec3{13, 22, 0}));
  // A broken feature is named by its line.
  EXPECT_NE(testing::input_error_of([&] {
              read_cityjson_text(text + "{\"type\": \"CityJSONFeature\"}\n", "t.city.jsonl");
            }).find("t.city.jsonl:4: (feature): missing \"vertices\""),
            std::string::npos);
}

TEST(CityJsonReader, MalformedFilesGiveOneLocatedError) {
  const std::string small = kSmall;
  const auto error_of = [](const std::string& text) {
    return testing::input_error_of([&] { read_cityjson_text(text, "bad.city.json"); });
  };
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = small;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  EXPECT_NE(error_of(small.substr(0, small.size() / 2)).find("bad.city.json:"), std::string::npos);
  EXPECT_NE(error_of(replaced("[[[[[0, 1, 2]]]], [[[[4, 5, 6]]", "[[[[[0, 1, 2]]]], [[[[4, 5, 60]]"))
                .find("bad.city.json: CityObjects[\"pair\"].geometry[0].boundaries[1][0][0][0][2]: vertex index 60 is "
                      "out of range (the file has 8 vertices)"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("[[[0, 1, 2, 3]], [[4, 5, 6, 7]]]", "[[[0, 1, 2, 3]], [[]]]"))
                .find("CityObjects[\"lawn\"].geometry[1].boundaries[1][0]: a ring without points"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("[[0, 1, 2, 2, 2, null]]", "[[0, 1, 2, 2, 7, null]]"))
                .find("semantic value 7 is not one of the geometry's 3"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("\"template\": 0", "\"template\": 3")).find("no template 3"), std::string::npos);
  EXPECT_NE(error_of(replaced("\"CityJSON\"", "\"CityGML\"")).find("bad.city.json: type: expected \"CityJSON\""),
            std::string::npos);
}

// A ring of one or two points encloses nothing (the CityGML reader met one in the OGC's
// Lyon sample, and refusing the file lost the district): as a hole it is dropped with
// its texture coordinates, as an outer ring its surface is kept and placed as one of
// zero area. What such a ring refers to is still checked.
TEST(CityJsonReader, RingsOfOneOrTwoPointsEncloseNothingAndStopNothing) {
  const std::string text = R"({"type": "CityJSON", "version": "2.0", "metadata": {"referenceSystem": "EPSG:7415"},
  "appearance": {"textures": [{"type": "PNG", "image": "roof.png"}],
                 "vertices-texture": [[0, 0], [1, 0], [1, 1], [0, 1]]},
  "vertices": [[85000, 446000, 0], [85010, 446000, 0], [85010, 446008, 0], [85000, 446008, 0],
               [85004, 446004, 0], [85005, 446004, 0]],
  "CityObjects": {"roof": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "2",
    "boundaries": [[[0, 1, 2, 3], [4, 5]], [[4, 5]], [[4]]],
    "texture": {"photo": {"values": [[[0, 0, 1, 2, 3], [0, 0, 1]], [[0, 0, 1]], [[null]]]}}}]}}})";
  const CityModel model = read_cityjson_text(text, "rings.city.json");
  const auto& surfaces = model.objects.at(0).surfaces;
  ASSERT_EQ(surfaces.size(), 3u);
  EXPECT_EQ(surfaces[0].rings.size(), 1u);                // the hole dropped,
  EXPECT_EQ(surfaces[0].texture_coordinates.size(), 1u);  // its texture coordinates with it
  EXPECT_EQ(surfaces[0].texture, 0);
  EXPECT_EQ(surfaces[1].rings.at(0).size(), 2u);
  EXPECT_EQ(surfaces[2].rings.at(0).size(), 1u);
  const PlacedCity placed = place_city_model(model, {}, "rings.city.json");
  EXPECT_EQ(placed.degenerate_surfaces, 2u);
  ASSERT_EQ(placed.objects.size(), 1u);
  EXPECT_EQ(placed.objects[0].mesh.triangles.size(), 2u);  // the 10 × 8 m roof, whole

  const auto error_of = [&](const std::string& from, const std::string& to) {
    std::string bad = text;
    bad.replace(bad.find(from), from.size(), to);
    return testing::input_error_of([&] { read_cityjson_text(bad, "bad.city.json"); });
  };
  EXPECT_NE(error_of("[4, 5]], [[4, 5]]", "[4, 60]], [[4, 5]]")
                .find("bad.city.json: CityObjects[\"roof\"].geometry[0].boundaries[0][1][1]: vertex index 60 is out of "
                      "range (the file has 6 vertices)"),
            std::string::npos);
  EXPECT_NE(error_of("[0, 0, 1]], [[0, 0, 1]]", "[0, 0]], [[0, 0, 1]]")
                .find("bad.city.json: CityObjects[\"roof\"].geometry[0].boundaries[0][1]: the texture values give 1 "
                      "coordinates for a ring of 2 points"),
            std::string::npos);
}

TEST(CityJsonReader, LodsAsTheVersionsWriteThem) {
  EXPECT_EQ(parse_lod("2.2"), 22);
  EXPECT_EQ(parse_lod("1"), 10);
  EXPECT_EQ(parse_lod("2.000000"), 20);
  EXPECT_EQ(parse_lod("1.300000"), 13);
  EXPECT_FALSE(parse_lod("5"));
  EXPECT_FALSE(parse_lod("2.7"));
  EXPECT_FALSE(parse_lod("x"));
}

}  // namespace
}  // namespace skylit
