// Per-object, per-material and probe statistics (assess/render_statistics.h) on a small
// image with hand-made layers, checked against values counted by hand; the pixel
// layers traced for a box straight ahead against its distance and normal in closed form.
#include "skylit/assess/render_statistics.h"

#include <gtest/gtest.h>

#include "../test_support.h"
#include "skylit/geometry/primitives.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit {
namespace {

Scene two_objects_one_material() {
  Scene scene;
  scene.materials.push_back({"brick", {}});
  scene.objects.push_back({"wall", {}, 0});
  scene.objects.push_back({"pier", {}, 0});
  return scene;
}

TEST(RenderStatistics, ObjectsMaterialsSkyAndProbesCountedByHand) {
  // 4 × 2 pixels: the top row sky (1, 2, 3, 4 cd/m²), the bottom row wall (10, 20, 30)
  // and pier (100).
  Scene scene = two_objects_one_material();
  scene.probes.push_back({"left column", 0, 0, 1, 2});
  scene.probes.push_back({"pier pixel", 3, 1, 4, 2});
  XyzImage image(4, 2);
  const double y[8] = {1, 2, 3, 4, 10, 20, 30, 100};
  for (int i = 0; i < 8; ++i) image.set(i % 4, i / 4, {0, y[i], 0});
  PixelLayers layers;
  layers.width = 4;
  layers.height = 2;
  layers.object = {-1, -1, -1, -1, 0, 0, 0, 1};
  const RenderStatistics s = render_statistics(image, layers, scene);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].name, "wall");
  EXPECT_EQ(s.objects[0].luminance.pixels, 3u);
  EXPECT_DOUBLE_EQ(s.objects[0].luminance.mean, 20);
  EXPECT_DOUBLE_EQ(s.objects[0].luminance.min, 10);
  EXPECT_DOUBLE_EQ(s.objects[0].luminance.max, 30);
  EXPECT_DOUBLE_EQ(s.objects[0].luminance.p50, 20);
  EXPECT_DOUBLE_EQ(s.objects[1].luminance.mean, 100);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].luminance.pixels, 4u);
  EXPECT_DOUBLE_EQ(s.materials[0].luminance.mean, 40);
  EXPECT_DOUBLE_EQ(s.materials[0].luminance.p95, 100);  // nearest rank of 4: round(0.95 · 3) = 3
  EXPECT_DOUBLE_EQ(s.sky.mean, 2.5);
  ASSERT_EQ(s.probes.size(), 2u);
  EXPECT_DOUBLE_EQ(s.probes[0].luminance.mean, 5.5);  // (1 + 10) / 2
  EXPECT_DOUBLE_EQ(s.probes[1].luminance.mean, 100);
  EXPECT_FALSE(s.glare);  // not a fisheye

  const std::string json = statistics_json(s);
  EXPECT_NE(
      json.find("{\"name\": \"wall\", \"luminance_cd_m2\": {\"pixels\": 3, \"mean\": 20, \"min\": 10, \"max\": 30"),
      std::string::npos)
      << json;
  const std::string csv = statistics_csv(s);
  EXPECT_NE(csv.find("probe,left column,2,5.5,1,10,"), std::string::npos) << csv;

  scene.probes.push_back({"outside", 3, 1, 5, 2});
  EXPECT_NE(testing::input_error_of([&] { render_statistics(image, layers, scene); }).find("probe \"outside\""),
            std::string::npos);
}

TEST(RenderStatistics, FisheyeViewsGetTheirGlare) {
  Scene scene = two_objects_one_material();
  scene.camera.position = {0, 0, 1.2};
  scene.camera.look_at = {0, 1, 1.2};
  scene.camera.projection = Projection::fisheye_equisolid;
  scene.camera.vertical_fov_deg = 180;
  XyzImage image(41, 41);
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 41; ++x) image.set(x, y, {0, 50, 0});
  PixelLayers layers;
  layers.object.assign(41 * 41, PixelLayers::kNoObject);
  const RenderStatistics s = render_statistics(image, layers, scene);
  ASSERT_TRUE(s.glare);
  EXPECT_NEAR(s.glare->dgp, 5.87e-5 * s.glare->vertical_illuminance_lx + 0.16, 1e-12);
  EXPECT_NE(statistics_json(s).find("\"glare\": {\"dgp\": "), std::string::npos);
}

TEST(PixelLayers, ABoxStraightAheadByItsDistanceAndNormal) {
  // Camera at the origin looking north at a box whose south face is the plane y = 10:
  // the centre pixel sees it at 10 m with normal (0, −1, 0); the corners see the sky.
  testing::TempDir dir;
  const std::string scene_text = R"({
    "camera": {"position": [0, 0, 5], "look_at": [0, 10, 5], "vertical_fov_deg": 40},
    "sun": {"altitude_deg": 40, "azimuth_deg": 135},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"name": "block", "type": "box", "material": "white", "min": [-2, 10, 3], "max": [2, 14, 7]}],
    "render": {"width": 21, "height": 21}
  })";
  const Scene scene = load_scene(dir.write("scene.json", scene_text));
  const PreparedScene prepared(scene);
  const PixelLayers layers = trace_pixel_layers(prepared);
  const std::size_t centre = 10 * 21 + 10;
  EXPECT_EQ(layers.object[centre], 0);
  EXPECT_NEAR(layers.distance_m[centre], 10, 1e-4);
  EXPECT_NEAR(layers.normal[3 * centre + 1], -1, 1e-6);
  EXPECT_EQ(layers.object[0], PixelLayers::kNoObject);
  EXPECT_EQ(layers.distance_m[0], 0);
}

}  // namespace
}  // namespace skylit
