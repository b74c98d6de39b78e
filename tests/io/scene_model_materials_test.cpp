// A model's own materials reach the scene per triangle; `material_overrides` replace
// them by glob pattern; the object's `material` covers triangles the file leaves bare;
// MeshLab's `Tr 1` is opaque and warned about.
#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_report.h"

namespace skylit {
namespace {

using testing::TempDir;

// A wall of two quads and a window triangle, materials Brick_red, Window_Glass, and
// one face with no material.
void write_house(const TempDir& dir) {
  dir.write("house.mtl",
            "newmtl Brick_red\nKd 0.5 0.2 0.1\nillum 1\n"
            "newmtl Window_Glass\nKd 0.1 0.1 0.1\nd 0.3\nNi 1.52\n");
  dir.write("house.obj",
            "mtllib house.mtl\nv 0 0 0\nv 4 0 0\nv 4 0 3\nv 0 0 3\nv 1 0 1\nv 2 0 1\nv 2 0 2\n"
            "usemtl Brick_red\nf 1 2 3 4\nusemtl Window_Glass\nf 5 6 7\nusemtl (null)\nf 1 2 3\n");
}

std::string scene_with(const std::string& overrides, const std::string& object_material) {
  return R"({"camera": {"position": [0, -20, 2], "look_at": [0, 0, 2]},
    "sun": {"altitude_deg": 40, "azimuth_deg": 135},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},)" +
         overrides + R"(
    "objects": [{"type": "mesh", "name": "house", "file": "house.obj", "up_axis": "z")" +
         object_material + "}]}";
}

std::string material_name(const Scene& scene, uint32_t triangle) {
  return scene.materials[scene.objects[0].material_of(triangle)].name;
}

TEST(SceneModelMaterials, FileMaterialsPerTriangleAndObjectMaterialForTheRest) {
  TempDir dir;
  write_house(dir);
  const Scene scene = load_scene(dir.write("scene.json", scene_with("", R"(, "material": "white")")));
  ASSERT_EQ(scene.objects[0].mesh.triangles.size(), 4u);
  EXPECT_EQ(material_name(scene, 0), "house/Brick_red");
  EXPECT_EQ(material_name(scene, 1), "house/Brick_red");
  EXPECT_EQ(material_name(scene, 2), "house/Window_Glass");
  EXPECT_EQ(material_name(scene, 3), "white");
  EXPECT_TRUE(std::holds_alternative<GlassMaterial>(scene.materials[scene.objects[0].material_of(2)].material));
  // Each file material is added once, however many triangles use it.
  EXPECT_EQ(scene.materials.size(), 3u);
}

TEST(SceneModelMaterials, TheMostSpecificMatchingPatternWins) {
  TempDir dir;
  write_house(dir);
  const Scene scene = load_scene(
      dir.write("scene.json", scene_with(R"("material_overrides": {"*Glass*": "glass", "Brick*": {"type": "diffuse",
                                  "reflectance": 0.3}, "*": "white"},)",
                                         R"(, "material": "white")")));
  EXPECT_EQ(material_name(scene, 0), "override Brick*");
  EXPECT_EQ(material_name(scene, 2), "override *Glass*");  // the preset, by name
  const auto& brick = std::get<DiffuseMaterial>(scene.materials[scene.objects[0].material_of(0)].material);
  EXPECT_NEAR(brick.reflectance[5], 0.3, 1e-6);
  // A pattern naming a scene material uses it rather than a copy.
  const Scene all_white = load_scene(
      dir.write("white.json", scene_with(R"("material_overrides": {"*": "white"},)", R"(, "material": "white")")));
  EXPECT_TRUE(all_white.objects[0].triangle_materials.empty());  // one material for all: no list
  EXPECT_EQ(all_white.materials[all_white.objects[0].material_index].name, "white");
}

TEST(SceneModelMaterials, BareTrianglesWithoutAnObjectMaterialAreAnError) {
  TempDir dir;
  write_house(dir);
  const auto file = dir.write("scene.json", scene_with("", ""));
  const std::string message = testing::input_error_of([&] { load_scene(file); });
  EXPECT_NE(message.find("objects[0]"), std::string::npos) << message;
  EXPECT_NE(message.find("no material"), std::string::npos) << message;
  // A bad inline override names its place.
  const auto bad = dir.write(
      "bad.json", scene_with(R"("material_overrides": {"Brick*": {"type": "chalk"}},)", R"(, "material": "white")"));
  EXPECT_NE(testing::input_error_of([&] { load_scene(bad); }).find("material_overrides.Brick*"), std::string::npos);
}

// MeshLab's `Tr 1` (an opacity) is an opaque material: `skylit info` shows what it
// became, and the warning names the object, the library, the material and the rule.
TEST(SceneModelMaterials, MeshLabsTrOfOneIsWarnedAboutAndOpaque) {
  TempDir dir;
  dir.write("scan.mtl", "newmtl material_0\nKd 0.6 0.5 0.4\nTr 1.000000\nillum 2\n");
  dir.write("house.obj", "mtllib scan.mtl\nv 0 0 0\nv 4 0 0\nv 4 0 3\nusemtl material_0\nf 1 2 3\n");
  const Scene scene = load_scene(dir.write("scene.json", scene_with("", "")));
  EXPECT_TRUE(std::holds_alternative<DiffuseMaterial>(scene.materials[scene.objects[0].material_of(0)].material));
  const std::string report = describe_objects(scene);
  EXPECT_NE(report.find("'material_0' → house/material_0 (diffuse; colour"), std::string::npos) << report;
  const auto warnings = scene_warnings(scene, false);
  EXPECT_NE(std::find(warnings.begin(), warnings.end(),
                      "object 'house': material library 'scan.mtl', material 'material_0': Tr 1 without d read as "
                      "MeshLab writes it, an opacity (opaque), not as 1 − d (clear glass)"),
            warnings.end());
}

}  // namespace
}  // namespace skylit
