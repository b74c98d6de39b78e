// Framed cameras show their objects whole and tight: projected by the renderer's own
// camera, the framed box's corners reach exactly kFramingFill of the way to the
// nearest image edge.
#include "skylit/scene/camera_framing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/camera.h"

namespace skylit {
namespace {

// The largest |offset| of the box's corners from the image centre, as a fraction of
// the half width or half height, whichever is larger; -1 if a corner is off the image.
double corner_reach(const Camera& camera, const BoundingBox& box, int width, int height) {
  const ImageCamera pinhole(camera, width, height);
  double reach = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner{k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y, k & 4 ? box.hi.z : box.lo.z};
    const auto p = pinhole.project(corner);
    if (!p) return -1;
    const double fx = std::abs(p->first - 0.5 * width) / (0.5 * width);
    const double fy = std::abs(p->second - 0.5 * height) / (0.5 * height);
    if (fx > 1 || fy > 1) return -1;
    reach = std::max({reach, fx, fy});
  }
  return reach;
}

TEST(CameraFraming, FromAnyDirectionTheBoxIsWholeAndFillsTheView) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    BoundingBox box;
    const Vec3 lo{-500 + 1000 * unit(rng), -500 + 1000 * unit(rng), 0};
    box.add(lo);
    box.add(lo + Vec3{1 + 80 * unit(rng), 1 + 80 * unit(rng), 1 + 200 * unit(rng)});
    const double azimuth = 360 * unit(rng), elevation = -10 + 100 * unit(rng), fov = 20 + 60 * unit(rng);
    const int width = 100 + static_cast<int>(900 * unit(rng)), height = 100 + static_cast<int>(900 * unit(rng));
    const Camera camera = frame_from_direction(box, azimuth, elevation, fov, double(width) / height);
    SCOPED_TRACE(trial);
    // The nearest corner to an edge reaches 95 % of the way to it (rounding: 1e-9).
    EXPECT_NEAR(corner_reach(camera, box, width, height), kFramingFill, 1e-9);
    // Standing where it was asked to.
    const Vec3 from_center = camera.position - box.center();
    if (elevation < 89) {
      EXPECT_NEAR(std::fmod(degrees(std::atan2(from_center.x, from_center.y)) + 360, 360), azimuth, 1e-6);
    }
    EXPECT_NEAR(degrees(std::asin(from_center.z / length(from_center))), elevation, 1e-6);
  }
}

TEST(CameraFraming, FromAnEyeFitsTheFieldOfView) {
  BoundingBox tower;
  tower.add({-10, -10, 0});
  tower.add({10, 10, 120});
  const Camera camera = frame_from_position(tower, {0, -200, 1.6}, 50, 16.0 / 9.0, true);
  EXPECT_NEAR(corner_reach(camera, tower, 1600, 900), kFramingFill, 1e-9);
  EXPECT_LT(camera.vertical_fov_deg, 50);  // a tower 200 m away needs less than the default
}

TEST(CameraFraming, SceneFileFramesNamedObjects) {
  testing::TempDir dir;
  const std::string head = R"({"sun": {"altitude_deg": 40, "azimuth_deg": 135},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"type": "plane", "material": "white", "size_m": 2000},
                {"type": "box", "name": "tower", "material": "white", "min": [100, 100, 0], "max": [120, 130, 90]}],
    "render": {"width": 64, "height": 48},)";
  const Scene scene = load_scene(
      dir.write("a.json", head + R"("camera": {"frame": ["tower"], "from_azimuth_deg": 135, "elevation_deg": 20}})"));
  const Vec3 center{110, 115, 45};
  EXPECT_NEAR(length(scene.camera.look_at - center), 0, 1e-9);
  EXPECT_NEAR(corner_reach(scene.camera, scene.objects[1].mesh.bounds(), 64, 48), kFramingFill, 1e-9);
  const Vec3 d = scene.camera.position - center;
  EXPECT_GT(d.x, 0);  // south-east of the tower
  EXPECT_LT(d.y, 0);
  const Scene eye =
      load_scene(dir.write("b.json", head + R"("camera": {"frame": ["tower"], "position": [0, 0, 1.6]}})"));
  EXPECT_EQ(eye.camera.position, Vec3(0, 0, 1.6));
  EXPECT_NEAR(corner_reach(eye.camera, eye.objects[1].mesh.bounds(), 64, 48), kFramingFill, 1e-9);
  const std::string unknown = testing::input_error_of([&] {
    load_scene(
        dir.write("c.json", head + R"("camera": {"frame": ["towr"], "from_azimuth_deg": 0, "elevation_deg": 5}})"));
  });
  EXPECT_NE(unknown.find("camera.frame[0]: no object is named 'towr'"), std::string::npos) << unknown;
}

}  // namespace
}  // namespace skylit
