// A city model in a scene (io/scene/city_reader.cpp): the default palette and the
// scene's city_materials, the model's centre as the site for the sun, and a malformed
// model refused by the program with one line and exit status 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "../../test_support.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_report.h"
#include "skylit/sun/solar_position.h"

namespace skylit {
namespace {

const std::filesystem::path kModels = std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/models";

std::string scene_with(const std::string& city, const std::string& site_and_time) {
  return R"({"camera": {"position": [0, -60, 20], "look_at": [0, 0, 5]}, )" + site_and_time +
         R"(, "materials": {"slate": {"type": "diffuse", "reflectance": 0.1}}, "objects": [)" + city + "]}";
}

// The materials of the triangles of one class, by name.
std::set<std::string> materials_of_class(const Scene& scene, const std::string& class_name) {
  std::set<std::string> names;
  for (const auto& c : scene.objects.at(0).city->classes)
    if (c.name == class_name) names.insert(c.material);
  return names;
}

TEST(CityScene, RoofsAndWallsGetTheirMaterialsAndTheScenesOverrides) {
  const auto file = kModels / "rotterdam_one.city.json";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared models";
  testing::TempDir dir;
  const auto scene_file = dir.write(
      "s.json", scene_with(R"({"type": "city", "name": "r", "file": ")" + file.string() +
                               R"(", "city_materials": {"Building.RoofSurface": "slate", "WallSurface": "tile"}})",
                           R"("time": "2026-06-21T12:00:00+02:00")"));
  const Scene scene = load_scene(scene_file);
  ASSERT_EQ(scene.objects.size(), 1u);
  const SceneObject& city = scene.objects[0];
  ASSERT_TRUE(city.city);
  EXPECT_EQ(materials_of_class(scene, "Building.RoofSurface"), std::set<std::string>{"slate"});
  EXPECT_EQ(materials_of_class(scene, "Building.WallSurface"), std::set<std::string>{"r/WallSurface"});
  EXPECT_EQ(materials_of_class(scene, "Building.GroundSurface"), std::set<std::string>{"city/GroundSurface"});
  // Every roof triangle carries the roof's material: count them through the mesh.
  size_t roof_triangles = 0;
  for (size_t t = 0; t < city.mesh.triangles.size(); ++t)
    roof_triangles += scene.materials[city.material_of(static_cast<uint32_t>(t))].name == "slate";
  size_t roof_class_triangles = 0;
  for (const auto& c : city.city->classes)
    if (c.name == "Building.RoofSurface") roof_class_triangles = c.triangles;
  EXPECT_GT(roof_triangles, 0u);
  EXPECT_EQ(roof_triangles, roof_class_triangles);
  // Roofs face up: their normals' mean points to the sky.
  Vec3 roof_normal{0, 0, 0};
  for (size_t t = 0; t < city.mesh.triangles.size(); ++t)
    if (scene.materials[city.material_of(static_cast<uint32_t>(t))].name == "slate") {
      const auto& tri = city.mesh.triangles[t];
      const auto& v = city.mesh.vertices;
      roof_normal += cross(v[tri[1]] - v[tri[0]], v[tri[2]] - v[tri[0]]);
    }
  EXPECT_GT(roof_normal.z, 0.5 * length(roof_normal));

  // No site: the model's centre became the site, and the sun stands where the SPA
  // puts it for that place.
  EXPECT_TRUE(city.city->site_from_model);
  const SolarPosition sun = solar_position(SiteLocation{city.city->latitude_deg, city.city->longitude_deg, 0},
                                           parse_offset_date_time("2026-06-21T12:00:00+02:00", "t"));
  EXPECT_NEAR(scene.sun.azimuth_deg, sun.azimuth_deg, 1e-9);
  EXPECT_NEAR(scene.sun.altitude_deg, sun.altitude_deg, 1e-9);
}

// Helsinki's models are CityJSON in EPSG:3879, whose definition puts northing first;
// CityJSON writes easting first whatever the CRS says, so reading them so is the rule,
// and a warning on every such file (as until 2026-12-07) only taught users to ignore it.
TEST(CityScene, ACityJsonFileInANorthingFirstCrsIsReadEastingFirstWithoutAWarning) {
  testing::TempDir dir;
  dir.write("block.city.json",
            R"({"type": "CityJSON", "version": "2.0", "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
    "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/3879"},
    "vertices": [[25496000, 6672000, 0], [25496010, 6672000, 0], [25496010, 6672010, 0], [25496000, 6672010, 0],
                 [25496000, 6672000, 10], [25496010, 6672000, 10], [25496010, 6672010, 10], [25496000, 6672010, 10]],
    "CityObjects": {"b": {"type": "Building", "geometry": [{"type": "Solid", "lod": "1",
      "boundaries": [[[[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]], [[0, 3, 2, 1]]]]}]}}})");
  const Scene scene =
      load_scene(dir.write("s.json", scene_with(R"({"type": "city", "name": "h", "file": "block.city.json"})",
                                                R"("time": "2026-06-21T12:00:00+03:00")")));
  const CitySource& source = *scene.objects.at(0).city;
  EXPECT_TRUE(source.axes_swapped);
  EXPECT_TRUE(source.axes_swapped_by_format);
  EXPECT_NEAR(source.latitude_deg, 60.1609, 1e-3);  // Helsinki, not the Gulf of Guinea
  EXPECT_NEAR(source.longitude_deg, 24.928, 1e-3);
  for (const std::string& w : scene_warnings(scene, false))
    EXPECT_EQ(w.find("other way round"), std::string::npos) << w;
  EXPECT_NE(describe_objects(scene).find("easting first, as the format writes it"), std::string::npos);
}

TEST(CityScene, MalformedModelIsOneLineAndExitStatusTwo) {
  testing::TempDir dir;
  dir.write("bad.city.json", R"({"type": "CityJSON", "version": "2.0", "vertices": [[0, 0, 0]],
    "metadata": {"referenceSystem": "EPSG:7415"},
    "CityObjects": {"b": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "1",
      "boundaries": [[[0, 0, 5]]]}]}}})");
  const auto scene_file = dir.write("s.json", scene_with(R"({"type": "city", "file": "bad.city.json"})",
                                                         R"("sun": {"altitude_deg": 30, "azimuth_deg": 180})"));
  const auto result = testing::run_skylit("info " + testing::quoted(scene_file));
  EXPECT_EQ(result.exit_status, 2);
  EXPECT_NE(result.output.find("bad.city.json: CityObjects[\"b\"].geometry[0].boundaries[0][0][2]: vertex index 5 is "
                               "out of range (the file has 1 vertices)"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
}

// A model whose every surface collapses once placed (a CityJSON transform's scale of
// 1e300 sends its vertices beyond any CRS) is said to be so, pointing at the
// coordinates and the transform, not at the region or the LoD.
TEST(CityScene, AModelOfOnlyCollapsedSurfacesPointsAtItsCoordinates) {
  testing::TempDir dir;
  dir.write("huge.city.json", R"({"type": "CityJSON", "version": "2.0",
    "transform": {"scale": [1e300, 1e300, 1e300], "translate": [85000, 447000, 0]},
    "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 1]], "metadata": {"referenceSystem": "EPSG:7415"},
    "CityObjects": {"b": {"type": "Building", "geometry": [{"type": "MultiSurface", "lod": "1",
      "boundaries": [[[0, 1, 2, 3]]]}]}}})");
  const auto scene_file = dir.write("s.json", scene_with(R"({"type": "city", "file": "huge.city.json"})",
                                                         R"("sun": {"altitude_deg": 30, "azimuth_deg": 180})"));
  const auto result = testing::run_skylit("info " + testing::quoted(scene_file));
  EXPECT_EQ(result.exit_status, 2);
  EXPECT_NE(result.output.find("all 1 surfaces of the city model have zero area once placed"), std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("in the region, at the LoD"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace skylit
