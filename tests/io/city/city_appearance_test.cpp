// City models' appearances (io/city/city_appearance.h, the readers' appearance parts):
// a texel looked up at a known place on a textured CityJSON cube and on a CityGML
// polygon is the one its texture coordinates name; X3D materials become the surfaces'
// reflectance; city_materials override the appearance, `appearance: false` and the
// theme choose; bad texture coordinates are one located error; the real models with
// appearances load, their missing images falling back to the palette with one warning.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "../../test_support.h"
#include "skylit/core/error.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/io/city/citygml_reader.h"
#include "skylit/io/city/cityjson_reader.h"
#include "skylit/io/image/image_encoders.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_report.h"
#include "skylit/material/surface_appearance.h"
#include "skylit/spectrum/rgb_to_spectrum.h"

namespace skylit {
namespace {

using testing::TempDir;

const std::filesystem::path kModels = std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/models";

// 2 × 2 texels, top row red and green, bottom row blue and white (8-bit sRGB).
void write_texture(const TempDir& dir, const std::string& name) {
  const uint8_t rgb[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  const Bytes png = encode_png_rgb8(2, 2, rgb);
  dir.write(name, std::string(png.begin(), png.end()));
}

// A 10 m cube in RD New + NAP (EPSG:7415) near Delft. Its first surface is the roof,
// textured with the whole image: corner (0, 0) of the image (its bottom left, t runs
// up) at the first vertex. The walls wear the X3D material of the theme.
std::string cube_json(const std::string& image) {
  return R"({"type": "CityJSON", "version": "2.0", "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415"},
    "vertices": [[85000, 447000, 0], [85010, 447000, 0], [85010, 447010, 0], [85000, 447010, 0],
                 [85000, 447000, 10], [85010, 447000, 10], [85010, 447010, 10], [85000, 447010, 10]],
    "appearance": {
      "materials": [{"name": "brick", "diffuseColor": [0.6, 0.1, 0.1]}, {"name": "pale", "diffuseColor": [0.7, 0.7, 0.6]}],
      "textures": [{"type": "PNG", "image": ")" +
         image + R"(", "wrapMode": "wrap"}],
      "vertices-texture": [[0, 0], [1, 0], [1, 1], [0, 1]]},
    "CityObjects": {"b": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "2",
      "boundaries": [[[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]], [[0, 3, 2, 1]]],
      "semantics": {"surfaces": [{"type": "RoofSurface"}, {"type": "WallSurface"}, {"type": "GroundSurface"}],
                    "values": [0, 1, 1, 1, 1, 2]},
      "material": {"colour": {"values": [null, 0, 0, 0, 0, null]}, "survey": {"value": 1}},
      "texture": {"photo": {"values": [[[0, 0, 1, 2, 3]], [[null]], [[null]], [[null]], [[null]], [[null]]]}}}]}}})";
}

std::string scene_json(const std::string& file, const std::string& more = "") {
  return R"({"camera": {"position": [0, -60, 20], "look_at": [0, 0, 5]}, "time": "2026-06-21T12:00:00+02:00",
    "materials": {"slate": {"type": "diffuse", "reflectance": 0.1}}, "objects": [{"type": "city", "name": "c", "file": ")" +
         file + R"(")" + more + "}]}";
}

// The colour the city object's texture gives straight below a point of its placed mesh,
// seen from 10 m above: the triangle hit, the texture coordinates at the hit from its
// corners', and the texel there (bilinear on the finest level) of its material's
// texture. (PreparedScene reads them the same way with a footprint filter:
// tests/io/model_textures_test.cpp; here the Embree hit alone keeps the test fast.)
Rgba texel_below(const Scene& scene, const Vec3& p) {
  const SceneObject& city = scene.objects.at(0);
  RayTracer tracer;
  tracer.add_mesh(city.mesh);
  tracer.commit();
  const std::optional<Hit> hit = tracer.intersect(Ray{{p.x, p.y, p.z + 10}, {0, 0, -1}});
  if (!hit) throw std::runtime_error("no hit");
  const auto& appearance = scene.materials[city.material_of(hit->triangle)].appearance;
  if (!appearance || !appearance->base_color) throw std::runtime_error("not textured");
  const CornerUvs& uv = city.corner_uvs.at(hit->triangle);
  const double b1 = hit->u, b2 = hit->v, b0 = 1 - b1 - b2;
  return appearance->base_color->bilinear(0, b0 * uv[0][0] + b1 * uv[1][0] + b2 * uv[2][0],
                                          b0 * uv[0][1] + b1 * uv[1][1] + b2 * uv[2][1]);
}

// The point of the placed quad whose first four vertices are a, b, c, d at fractions
// (f, g) along a→b and a→d: there the texture coordinates are (f, g) when a, b, d
// carry (0, 0), (1, 0), (0, 1).
Vec3 on_quad(const TriangleMesh& mesh, double f, double g) {
  const Vec3 a = mesh.vertices[0], b = mesh.vertices[1], d = mesh.vertices[3];
  return a + f * (b - a) + g * (d - a);
}

void expect_texel(const Rgba& t, float r, float g, float b) {
  // At a texel's centre the bilinear look-up is the texel itself; the placed points are
  // within millimetres of the centre (1e-4 of a 5 m texel, PROJ's round trip), which
  // blends in a neighbour by less than 1e-3. A wrong texel would be off by 1.
  EXPECT_NEAR(t[0], r, 1e-3);
  EXPECT_NEAR(t[1], g, 1e-3);
  EXPECT_NEAR(t[2], b, 1e-3);
}

const NamedMaterial& material_at(const Scene& scene, size_t triangle) {
  return scene.materials[scene.objects[0].material_of(static_cast<uint32_t>(triangle))];
}

// The first triangle of a wall (the second surface; the roof gives two triangles).
constexpr size_t kWallTriangle = 2;

TEST(CityAppearance, CityJsonCubeTexelsAndMaterials) {
  TempDir dir;
  write_texture(dir, "roof.png");
  dir.write("cube.city.json", cube_json("roof.png"));
  const Scene scene = load_scene(dir.write("s.json", scene_json("cube.city.json")));
  const SceneObject& city = scene.objects.at(0);
  ASSERT_EQ(city.corner_uvs.size(), city.mesh.triangles.size());
  // The roof's first four vertices are the ring's, in its order, 10 m up.
  for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(city.mesh.vertices[k].z, 10.0, 1e-3);
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.25, 0.25)), 0, 0, 1);  // bottom left: blue
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.75, 0.25)), 1, 1, 1);  // bottom right: white
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.25, 0.75)), 1, 0, 0);  // top left: red
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.75, 0.75)), 0, 1, 0);  // top right: green
  // The walls: theme "colour" (the first) gives them brick, whose reflectance is the
  // colour's Jakob–Hanika spectrum; the ground has no appearance: the palette's.
  EXPECT_EQ(material_at(scene, kWallTriangle).name, "c/brick");
  const auto* wall = std::get_if<DiffuseMaterial>(&material_at(scene, kWallTriangle).material);
  ASSERT_NE(wall, nullptr);
  const Spectrum expected = reflectance_from_linear_srgb({0.6, 0.1, 0.1});
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(wall->reflectance[i], expected[i], 1e-9);
  EXPECT_EQ(material_at(scene, city.mesh.triangles.size() - 1).name, "city/GroundSurface");
  EXPECT_EQ(city.city->appearance_triangles, 10u);  // roof 2 + walls 8
  EXPECT_TRUE(scene_warnings(scene, false).empty());
}

TEST(CityAppearance, OverridesThemesAndTheSwitch) {
  TempDir dir;
  write_texture(dir, "roof.png");
  dir.write("cube.city.json", cube_json("roof.png"));
  // city_materials beat the appearance.
  const Scene overridden =
      load_scene(dir.write("o.json", scene_json("cube.city.json", R"(, "city_materials": {"WallSurface": "slate"})")));
  EXPECT_EQ(material_at(overridden, kWallTriangle).name, "slate");
  EXPECT_EQ(material_at(overridden, 0).name, "c/roof.png");
  // Another theme: every surface wears "pale".
  const Scene survey =
      load_scene(dir.write("t.json", scene_json("cube.city.json", R"(, "appearance_theme": "survey")")));
  EXPECT_EQ(material_at(survey, 0).name, "c/pale");
  EXPECT_EQ(material_at(survey, kWallTriangle).name, "c/pale");
  EXPECT_TRUE(survey.objects[0].corner_uvs.empty());  // that theme has no texture
  // No appearance: the palette.
  const Scene plain = load_scene(dir.write("p.json", scene_json("cube.city.json", R"(, "appearance": false)")));
  EXPECT_EQ(material_at(plain, 0).name, "city/RoofSurface");
  EXPECT_EQ(material_at(plain, kWallTriangle).name, "city/WallSurface");
  // A theme the file does not have is an error naming the file's.
  const std::string message = testing::input_error_of(
      [&] { load_scene(dir.write("x.json", scene_json("cube.city.json", R"(, "appearance_theme": "winter")"))); });
  EXPECT_NE(message.find("no appearance theme 'winter' (its themes: 'colour', 'survey', 'photo')"), std::string::npos)
      << message;
}

TEST(CityAppearance, AMissingImageFallsBackWithOneWarning) {
  TempDir dir;
  dir.write("cube.city.json", cube_json("textures/roof.png"));
  const Scene scene = load_scene(dir.write("s.json", scene_json("cube.city.json")));
  EXPECT_EQ(material_at(scene, 0).name, "city/RoofSurface");
  EXPECT_EQ(material_at(scene, kWallTriangle).name, "c/brick");
  const auto warnings = scene_warnings(scene, false);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'textures/roof.png'"), std::string::npos) << warnings[0];
}

TEST(CityAppearance, BadCityJsonTextureValuesAreLocated) {
  const std::string good = cube_json("roof.png");
  const auto error_of = [](const std::string& text) {
    return testing::input_error_of([&] { read_cityjson_text(text, "cube.city.json"); });
  };
  std::string short_ring = good;
  short_ring.replace(short_ring.find("[[0, 0, 1, 2, 3]]"), 17, "[[0, 0, 1, 2]]");
  EXPECT_NE(error_of(short_ring)
                .find("cube.city.json: CityObjects[\"b\"].geometry[0].boundaries[0][0]: the texture values give 3 "
                      "coordinates for a ring of 4 points"),
            std::string::npos)
      << error_of(short_ring);
  std::string bad_uv = good;
  bad_uv.replace(bad_uv.find("[[0, 0, 1, 2, 3]]"), 17, "[[0, 0, 1, 2, 9]]");
  EXPECT_NE(error_of(bad_uv).find("texture vertex 9 is out of range (the file has 4)"), std::string::npos);
}

// An untextured surface is [[null]] whatever its rings (CityJSON 2.0, Texture object): a
// wall with a window hole and [[null]] loads, untextured, its hole kept (the 3DGI
// conformance corpus's geometry_texture_multisolid was refused).
TEST(CityAppearance, AnUntexturedSurfaceWithAHoleIsOneNull) {
  std::string holed = cube_json("roof.png");
  holed.replace(holed.find("[85000, 447010, 10]]"), 20,
                "[85000, 447010, 10], [85004, 447000, 4], [85006, 447000, 4], [85006, 447000, 6], [85004, 447000, 6]]");
  holed.replace(holed.find("[[0, 1, 5, 4]]"), 14, "[[0, 1, 5, 4], [8, 11, 10, 9]]");
  const CityModel model = read_cityjson_text(holed, "cube.city.json");
  ASSERT_EQ(model.objects.size(), 1u);
  const CitySurface& wall = model.objects[0].surfaces.at(1);
  EXPECT_EQ(wall.rings.size(), 2u);
  EXPECT_EQ(wall.texture, CitySurface::kNone);
  EXPECT_EQ(model.objects[0].surfaces.at(0).texture, 0);  // the roof keeps its own
}

TEST(CityAppearance, CityJsonSeqFeaturesMayBringTheirOwnAppearance) {
  const std::string header =
      R"({"type": "CityJSON", "version": "2.0", "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
        "appearance": {"materials": [{"name": "shared"}]}, "CityObjects": {}, "vertices": []})";
  const auto feature = [](const std::string& id, const std::string& appearance) {
    return R"({"type": "CityJSONFeature", "id": ")" + id + R"(", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],)" +
           appearance + R"( "CityObjects": {")" + id +
           R"(": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]],
             "material": {"m": {"values": [0]}}}]}}})";
  };
  const auto one_line = [](std::string line) {
    std::replace(line.begin(), line.end(), '\n', ' ');
    return line + "\n";
  };
  const std::string text =
      one_line(header) + one_line(feature("a", "")) +
      one_line(feature("b", R"("appearance": {"materials": [{"name": "own", "diffuseColor": [0.1, 0.2, 0.3]}]},)"));
  const CityModel model = read_cityjson_text(text, "seq.city.jsonl");
  ASSERT_EQ(model.objects.size(), 2u);
  ASSERT_EQ(model.materials.size(), 2u);
  EXPECT_EQ(model.materials[static_cast<size_t>(model.objects[0].surfaces.at(0).material)].name, "shared");
  EXPECT_EQ(model.materials[static_cast<size_t>(model.objects[1].surfaces.at(0).material)].name, "own");
}

// One horizontal 10 m square in JGD2011 latitude, longitude and height (PLATEAU's
// EPSG:6697), textured by a ParameterizedTexture of theme "rgbTexture", and a second
// square beside it with an X3DMaterial of the same theme.
std::string plateau_gml(const std::string& ring_ref, const std::string& coordinates) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
  xmlns:gml="http://www.opengis.net/gml" xmlns:app="http://www.opengis.net/citygml/appearance/2.0">
<core:cityObjectMember><bldg:Building gml:id="b1"><bldg:boundedBy><bldg:RoofSurface><bldg:lod2MultiSurface>
<gml:MultiSurface srsName="http://www.opengis.net/def/crs/EPSG/0/6697" srsDimension="3">
<gml:surfaceMember><gml:Polygon gml:id="p1"><gml:exterior><gml:LinearRing gml:id="r1"><gml:posList>
35.5 139.7 10 35.5 139.70011 10 35.50009 139.70011 10 35.50009 139.7 10 35.5 139.7 10
</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
<gml:surfaceMember><gml:Polygon gml:id="p2"><gml:exterior><gml:LinearRing gml:id="r2"><gml:posList>
35.5 139.70022 10 35.5 139.70033 10 35.50009 139.70033 10 35.50009 139.70022 10 35.5 139.70022 10
</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
</gml:MultiSurface></bldg:lod2MultiSurface></bldg:RoofSurface></bldg:boundedBy></bldg:Building></core:cityObjectMember>
<app:appearanceMember><app:Appearance><app:theme>rgbTexture</app:theme>
<app:surfaceDataMember><app:ParameterizedTexture><app:imageURI>tex/roof.png</app:imageURI>
<app:target uri="#p1"><app:TexCoordList>
<app:textureCoordinates ring=")" +
         ring_ref + R"(">)" + coordinates + R"(</app:textureCoordinates>
</app:TexCoordList></app:target></app:ParameterizedTexture></app:surfaceDataMember>
<app:surfaceDataMember><app:X3DMaterial gml:id="tile"><app:diffuseColor>0.2 0.3 0.5</app:diffuseColor>
<app:specularColor>0.04 0.04 0.04</app:specularColor><app:shininess>0.5</app:shininess>
<app:target>#p2</app:target></app:X3DMaterial></app:surfaceDataMember>
</app:Appearance></app:appearanceMember>
</core:CityModel>
)";
}

// Latitude runs first in EPSG:6697: the ring goes north-west... as (lat, lon): its
// first corner is the south-west one, the second the south-east (east of it), the
// fourth the north-west; the coordinates give them (0, 0), (1, 0), (0, 1).
constexpr const char* kSquareCoordinates = "0 0 1 0 1 1 0 1 0 0";

TEST(CityAppearance, CityGmlParameterizedTextureAndX3dMaterial) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "tex");
  write_texture(dir, "tex/roof.png");
  dir.write("block.gml", plateau_gml("#r1", kSquareCoordinates));
  const Scene scene = load_scene(dir.write("s.json", scene_json("block.gml")));
  const SceneObject& city = scene.objects.at(0);
  ASSERT_EQ(city.corner_uvs.size(), city.mesh.triangles.size());
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.25, 0.25)), 0, 0, 1);
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.75, 0.25)), 1, 1, 1);
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.25, 0.75)), 1, 0, 0);
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.75, 0.75)), 0, 1, 0);
  // The second square: its X3D material, a coat (a specular colour) over its diffuse
  // colour.
  const NamedMaterial& tile = material_at(scene, city.mesh.triangles.size() - 1);
  EXPECT_EQ(tile.name, "c/tile");
  EXPECT_TRUE(std::holds_alternative<CookTorranceMaterial>(tile.material));
  EXPECT_EQ(city.city->appearance_theme, "rgbTexture");
  // The same file named as Berlin's downloads are (.citygml) reads the same.
  dir.write("block.citygml", plateau_gml("#r1", kSquareCoordinates));
  const Scene renamed = load_scene(dir.write("r.json", scene_json("block.citygml")));
  EXPECT_EQ(renamed.objects.at(0).mesh.triangles.size(), city.mesh.triangles.size());
}

// CityGML 3.0 names a TexCoordList's ring in an element after its coordinates
// (<app:ring>#r1</app:ring>) and its target as text in a TextureAssociation; the OGC's
// PLATEAU 3.0 sample was refused ("ring='#' names no ring"). The same square reads the
// same texels as in 2.0.
TEST(CityAppearance, CityGml3TexCoordListWithItsRingElement) {
  std::string gml = plateau_gml("#r1", kSquareCoordinates);
  const std::string from = std::string(R"(<app:target uri="#p1"><app:TexCoordList>
<app:textureCoordinates ring="#r1">)") +
                           kSquareCoordinates + R"(</app:textureCoordinates>
</app:TexCoordList></app:target>)";
  const std::string to =
      std::string(R"(<app:textureParameterization><app:TextureAssociation><app:target>#p1</app:target>
<app:textureParameterization><app:TexCoordList><app:textureCoordinates>)") +
      kSquareCoordinates + R"(</app:textureCoordinates><app:ring>#r1</app:ring>
</app:TexCoordList></app:textureParameterization></app:TextureAssociation></app:textureParameterization>)";
  ASSERT_NE(gml.find(from), std::string::npos);
  gml.replace(gml.find(from), from.size(), to);
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "tex");
  write_texture(dir, "tex/roof.png");
  dir.write("block.gml", gml);
  const Scene scene = load_scene(dir.write("s.json", scene_json("block.gml")));
  const SceneObject& city = scene.objects.at(0);
  ASSERT_EQ(city.corner_uvs.size(), city.mesh.triangles.size());
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.25, 0.25)), 0, 0, 1);
  expect_texel(texel_below(scene, on_quad(city.mesh, 0.75, 0.75)), 0, 1, 0);
  // A ring element with no coordinates before it is one located error.
  std::string stray = gml;
  stray.replace(stray.find("<app:ring>"), 0, "<app:ring>#r1</app:ring>");
  EXPECT_NE(testing::input_error_of([&] {
              parse_citygml(stray, "block.gml");
            }).find("app:ring '#r1' follows no app:textureCoordinates of its own"),
            std::string::npos);
}

TEST(CityAppearance, BadCityGmlTextureCoordinatesAreOneLocatedError) {
  const auto error_of = [](const std::string& text) {
    return testing::input_error_of([&] { parse_citygml(text, "block.gml"); });
  };
  // The textureCoordinates element is on line 16 of the file.
  EXPECT_EQ(error_of(plateau_gml("#r9", kSquareCoordinates)),
            "block.gml:16: app:textureCoordinates ring='#r9' names no ring in the file");
  EXPECT_EQ(error_of(plateau_gml("#r1", "0 0 1 0 1 1")),
            "block.gml:16: app:textureCoordinates give 6 numbers for ring '#r1' of 4 points: expected two per point");
  // Without appearances nothing of them is read, nor checked.
  CityGmlOptions plain;
  plain.appearance.read = false;
  EXPECT_NO_THROW(parse_citygml(plateau_gml("#r9", kSquareCoordinates), "block.gml", plain));
}

TEST(CityAppearance, RealModelsLoadWithTheirAppearancesOrTheFallback) {
  const auto rotterdam = kModels / "rotterdam_one.city.json";
  const auto plateau = kModels / "plateau_53392642_bldg_6697_op2.gml";
  if (!std::filesystem::exists(rotterdam) || !std::filesystem::exists(plateau)) GTEST_SKIP() << "no shared models";
  // Rotterdam: theme rgbTexture, 6 JPEG textures on 13 of its 14 surfaces.
  const CityModel r = read_cityjson_file(rotterdam);
  EXPECT_EQ(r.texture_theme, "rgbTexture");
  EXPECT_EQ(r.textures.size(), 6u);
  size_t textured = 0;
  for (const CitySurface& s : r.objects.at(0).surfaces) textured += s.texture != CitySurface::kNone;
  EXPECT_EQ(textured, 13u);
  // PLATEAU: the same theme, textures on most polygons, coordinates within [0, 1].
  const CityModel p = read_citygml_file(plateau);
  EXPECT_EQ(p.texture_theme, "rgbTexture");
  size_t polygons = 0, plateau_textured = 0;
  for (const CityObject& o : p.objects)
    for (const CitySurface& s : o.surfaces) {
      ++polygons;
      if (s.texture == CitySurface::kNone) continue;
      ++plateau_textured;
      for (const auto& ring : s.texture_coordinates)
        for (const auto& st : ring) EXPECT_TRUE(st[0] >= 0 && st[0] <= 1 && st[1] >= 0 && st[1] <= 1);
    }
  EXPECT_GT(plateau_textured, polygons / 2);
  // Neither ships its images: scenes load, the palette stands in, one warning each.
  TempDir dir;
  for (const auto& file : {rotterdam, plateau}) {
    const Scene scene = load_scene(dir.write("s.json", scene_json(file.string())));
    const CitySource& source = *scene.objects.at(0).city;
    EXPECT_FALSE(source.missing_texture_images.empty());
    EXPECT_EQ(source.appearance_triangles, 0u);
    EXPECT_TRUE(scene.objects[0].corner_uvs.empty() ||
                scene.objects[0].corner_uvs.size() == scene.objects[0].mesh.triangles.size());
    const auto warnings = scene_warnings(scene, false);
    EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(),
                            [](const std::string& w) { return w.find("texture image") != std::string::npos; }),
              1);
  }
}

}  // namespace
}  // namespace skylit
