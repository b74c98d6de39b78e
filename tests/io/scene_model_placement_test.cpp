// Units, centring and placing on the ground of mesh objects, and the warnings that
// catch a model in the wrong unit, far away, floating or sunk, a camera inside a
// building or facing one wall, and overrides that match nothing.
#include <gtest/gtest.h>

#include <algorithm>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_report.h"

namespace skylit {
namespace {

using testing::TempDir;

// A closed box 12 000 × 8 000 × 6 000 (a 12 m house in mm) in survey coordinates,
// its base 150 000 units below the file's zero.
void write_box_in_mm(const TempDir& dir) {
  std::string obj;
  const double x0 = 500000e3, y0 = 4000000e3, z0 = -150e3;
  for (double z : {z0, z0 + 6000})
    for (double y : {y0, y0 + 8000})
      for (double x : {x0, x0 + 12000})
        obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  // Outward faces of the box (vertices 1–8: bit 0 x, bit 1 y, bit 2 z).
  obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  dir.write("house_mm.obj", obj);
}

std::string scene_json(const std::string& object_keys, const std::string& camera = "[0, -40, 2]") {
  return R"({"camera": {"position": )" + camera + R"(, "look_at": [0, 0, 3]},
    "sun": {"altitude_deg": 40, "azimuth_deg": 135},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"type": "mesh", "name": "house", "file": "house_mm.obj", "material": "white")" +
         object_keys + "}]}";
}

bool any_contains(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

TEST(SceneModelPlacement, UnitsCentreAndGround) {
  TempDir dir;
  write_box_in_mm(dir);
  const Scene scene =
      load_scene(dir.write("scene.json", scene_json(R"(, "units": "mm", "center": true, "place_on_ground": true)")));
  const BoundingBox box = scene.objects[0].mesh.bounds();
  // mm → m is exact enough in double: 1e-9 m.
  EXPECT_NEAR(box.lo.x, -6, 1e-9);
  EXPECT_NEAR(box.hi.x, 6, 1e-9);
  EXPECT_NEAR(box.lo.y, -4, 1e-9);
  EXPECT_NEAR(box.hi.y, 4, 1e-9);
  EXPECT_NEAR(box.lo.z, 1e-3, 1e-9);  // a millimetre above a ground plane, not in it
  EXPECT_NEAR(box.hi.z, 6.001, 1e-9);
  const ModelSource& source = *scene.objects[0].source;
  EXPECT_EQ(source.units, "mm");
  EXPECT_NEAR(source.offset_m.x, -500006, 1e-6);  // the survey easting removed, recorded
  EXPECT_NEAR(source.offset_m.z, 150.001, 1e-9);
  EXPECT_TRUE(scene_warnings(scene, true).empty()) << scene_warnings(scene, true)[0];
  const std::string report = describe_objects(scene);
  EXPECT_NE(report.find("12 triangles"), std::string::npos) << report;
  EXPECT_NE(report.find("extent 12.00 × 8.00 × 6.00 m"), std::string::npos) << report;
  EXPECT_NE(report.find("units mm"), std::string::npos) << report;

  // Feet and inches by their international definitions.
  const Scene feet = load_scene(dir.write("ft.json", scene_json(R"(, "units": "ft", "center": true)")));
  EXPECT_NEAR(feet.objects[0].mesh.bounds().size().x, 12000 * 0.3048, 1e-6);
  EXPECT_NE(testing::input_error_of([&] {
              load_scene(dir.write("yd.json", scene_json(R"(, "units": "yd")")));
            }).find("objects[0].units"),
            std::string::npos);
}

TEST(SceneModelPlacement, WarningsForLikelyMistakes) {
  TempDir dir;
  write_box_in_mm(dir);
  // Read as metres: 12 km across, 150 km down, 4 000 km from the origin.
  const Scene raw = load_scene(dir.write("raw.json", scene_json("")));
  const auto warnings = scene_warnings(raw, false);
  EXPECT_TRUE(any_contains(warnings, "km from the origin")) << warnings.size();
  EXPECT_TRUE(any_contains(warnings, "sinks 150000.00 m below the ground"));
  EXPECT_TRUE(any_contains(warnings, "is 12000 m across"));
  // In mm and centred, but floating 2 m up.
  const Scene floating = load_scene(dir.write(
      "float.json", scene_json(R"(, "units": "mm", "center": true, "transform": {"translate": [0, 0, 152]})")));
  const auto w = scene_warnings(floating, false);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("floats 2.00 m above"), std::string::npos) << w[0];
}

TEST(SceneModelPlacement, CameraInsideOrFacingOneWall) {
  TempDir dir;
  write_box_in_mm(dir);
  const std::string placed = R"(, "units": "mm", "center": true, "place_on_ground": true)";
  const Scene inside = load_scene(dir.write("in.json", scene_json(placed, "[1, 0, 2]")));
  EXPECT_TRUE(any_contains(scene_warnings(inside, true), "inside a closed mesh (object 'house')"));
  EXPECT_FALSE(any_contains(scene_warnings(inside, false), "inside"));  // only when asked
  // 0.5 m in front of the south wall, looking at it.
  const Scene facing = load_scene(dir.write("wall.json", scene_json(placed, "[0, -4.5, 2]")));
  const auto w = scene_warnings(facing, true);
  EXPECT_TRUE(any_contains(w, "nothing but one surface of object 'house'"));
  EXPECT_FALSE(any_contains(w, "inside"));
}

TEST(SceneModelPlacement, OverridesThatMatchNothingAreReported) {
  TempDir dir;
  dir.write("m.mtl", "newmtl Brick\nKd 0.5 0.2 0.1\n");
  dir.write("m.obj", "mtllib m.mtl\nmtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Brick\nf 1 2 3\n");
  const Scene scene = load_scene(dir.write("s.json", R"({"camera": {"position": [0, -40, 2], "look_at": [0, 0, 3]},
    "sun": {"altitude_deg": 40, "azimuth_deg": 135}, "materials": {},
    "material_overrides": {"*Glas*": "glass"},
    "objects": [{"type": "mesh", "name": "m", "file": "m.obj", "units": "cm"}]})"));
  const auto w = scene_warnings(scene, false);
  EXPECT_TRUE(any_contains(w, "pattern '*Glas*' matched no material"));
  EXPECT_TRUE(any_contains(w, "material 'Brick' matched no override"));
  EXPECT_TRUE(any_contains(w, "library 'gone.mtl' not found"));
  EXPECT_TRUE(any_contains(w, "only 0.010 m across"));
  EXPECT_NE(describe_objects(scene).find("'Brick' → m/Brick (diffuse; colour"), std::string::npos)
      << describe_objects(scene);
}

}  // namespace
}  // namespace skylit
