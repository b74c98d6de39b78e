// Light in a street canyon (issue 14, item 1): the shaded wall of an east–west street
// between two long blocks of grey Lambertian walls, at five heights, from the fast
// method against the path-traced reference (render/path_integrator.h), which carries
// every bounce between the walls, the street and the sky. The fast method's obstacles
// are lit by the sky they see themselves (render/obstacle_sky_light.h); lit by the
// whole unobstructed sky, a facade across a narrow street was credited with sky it
// cannot see.
//
// `render.obstacle_light = "own_sky"`, the default (docs/sky-light.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../test_support.h"
#include "path_luminance.h"
#include "skylit/geometry/primitives.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/path_integrator.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

constexpr double kWidth = 12;        // the street, wall to wall, m
constexpr double kHalfLength = 150;  // each block runs 300 m along x

// The sun in the south at 30°: the blocks' north faces (the south block's, across the
// street from the sunlit one) are in shade. With `strip_m` the north block's sunlit face
// is cut into vertical strips that wide (as a CAD export cuts a wall around its
// windows), a separate mesh 1 cm before the block.
Scene canyon(double height_over_width, double strip_m = 0, double width_m = kWidth, double sun_azimuth_deg = 180) {
  const double h = height_over_width * width_m, half = width_m / 2;
  Scene scene;
  scene.camera = Camera{{0, 0, 1.6}, {0, 100, 1.6}, {0, 0, 1}, 50.0};
  scene.sun = Sun{30, sun_azimuth_deg};
  scene.render.obstacles_own_sky = true;
  scene.atmosphere.ground_albedo = 0.3;
  scene.materials.push_back({"grey", DiffuseMaterial{Spectrum(0.3f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 20000), 0});
  scene.objects.push_back({"south block", make_box({-kHalfLength, -half - 20, 0}, {kHalfLength, -half, h}), 0});
  if (strip_m <= 0) {
    scene.objects.push_back({"north block", make_box({-kHalfLength, half, 0}, {kHalfLength, half + 20, h}), 0});
    return scene;
  }
  scene.objects.push_back({"north block", make_box({-kHalfLength, half + 0.01, 0}, {kHalfLength, half + 20, h}), 0});
  TriangleMesh face;
  for (double x0 = -kHalfLength; x0 < kHalfLength - 1e-9; x0 += strip_m) {
    const auto n = static_cast<uint32_t>(face.vertices.size());
    face.vertices.insert(face.vertices.end(),
                         {{x0, half, 0}, {x0 + strip_m, half, 0}, {x0 + strip_m, half, h}, {x0, half, h}});
    face.triangles.push_back({n, n + 2, n + 1});
    face.triangles.push_back({n, n + 3, n + 2});
  }
  scene.objects.push_back({"north block's face", face, 0});
  return scene;
}

using testing::Estimate;
using testing::path_luminance;

// The shaded wall at 10, 30, 50, 70 and 90 % of its height, each seen straight on from
// 0.3 m: the fast method within `tolerance` plus three standard errors of the reference.
void compare_shaded_wall(double height_over_width, int paths, double tolerance, double width_m = kWidth,
                         double sun_azimuth_deg = 180) {
  const Scene scene = canyon(height_over_width, 0, width_m, sun_azimuth_deg);
  const Renderer fast(scene);
  const PathIntegrator path(fast.prepared());
  const double h = height_over_width * width_m;
  for (double share : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const Vec3 on_wall{0, -width_m / 2, share * h};
    const Ray ray{on_wall + Vec3{0, 0.3, 0}, {0, -1, 0}};
    const double expected = luminance(fast.radiance(ray));
    const Estimate reference = path_luminance(path, ray, paths, 23);
    const double ratio = expected / reference.mean;
    std::printf(
        "[Canyon] %4.1f m, h/w %.0f, sun at %3.0f°, %2.0f %% up: fast %8.2f path %8.2f ± %5.2f cd/m2, ratio %.3f\n",
        width_m, height_over_width, sun_azimuth_deg, 100 * share, expected, reference.mean, reference.standard_error,
        ratio);
    EXPECT_NEAR(expected, reference.mean, tolerance * reference.mean + 3 * reference.standard_error)
        << width_m << " m, h/w " << height_over_width << ", sun at " << sun_azimuth_deg << "°, " << share
        << " of the height";
  }
}

TEST(CanyonLight, ShadedWallAgainstThePathTracer) {
  // 200,000 paths a point: standard errors 0.2 % at the top to 1.1 % at the foot of the
  // deepest canyon, where the wall is 54 cd/m² against 960 at its top. (With 16,000, 3.7 %
  // there: three of them let a wall 14 % off pass, and hid the fast path's +7 % at that
  // foot until 2026-12-07.) 3 % is the bound. About 9 s.
  for (double h_over_w : {1.0, 2.0, 4.0}) compare_shaded_wall(h_over_w, 200000, 0.03);
}

TEST(CanyonLight, TheShadedWallHoldsAtOtherWidths) {
  // The canyon has almost no scale of its own, but the obstacles' patches are squares
  // of power-of-two metres: where the sunlit wall's shadow edge fell on them changed with
  // the width, and the h/w 2 wall's middle read 3.8 % too bright at 5 and 20 m where it
  // held at 12 m (docs/sky-light.md, "At other widths"); and the fixed directions'
  // misjudgement of the sky slit and the sunlit band at the top of the far wall moved
  // with where their outlines fell among the directions: the h/w 2 foot read 0.955 and
  // 0.959 (docs/sky-light.md, "Outlines that matter"). The 3 % at those widths
  // too, h/w 2 and 4, 200,000 paths a point. About 14 s.
  for (double h_over_w : {2.0, 4.0})
    for (double width : {5.0, 20.0}) compare_shaded_wall(h_over_w, 200000, 0.03, width);
}

TEST(CanyonLight, TheShadedWallHoldsUnderAnObliqueSun) {
  // The sun 30° off the street's normal (azimuth 150°): the sunlit band on the far wall
  // and the shadow on the street are no longer parallel to the walls. Before the
  // outlines that matter and the turned directions (docs/sky-light.md) the h/w 4 foot
  // read 1.096 of the path tracer here (300,000 paths), a case the tests above did not
  // see; measured after: h/w 2 0.978–1.003, h/w 4 0.967–1.003. 3 %, 200,000 paths a
  // point. About 8 s.
  for (double h_over_w : {2.0, 4.0}) compare_shaded_wall(h_over_w, 200000, 0.03, kWidth, 150);
}

TEST(CanyonLight, TheShadedWallDoesNotDependOnHowTheSunlitOneIsCutIntoTriangles) {
  // The sunlit wall across the street in strips of 1 m and 0.1 m (the obstacles' patches
  // belong to its plane, not its triangles): the shaded wall at five heights within 1 %
  // of the same canyon with the wall of two triangles (the patches' squares and points
  // are the same; the probes and the strips' edges move single-precision bits). Kept
  // per triangle, the strips read 0.96–1.12 (1 m) and 0.82–1.02 (0.1 m) of the path
  // tracer where the whole wall read 0.92–1.13; now 0.90–1.04 (docs/sky-light.md). 2 s.
  for (double h_over_w : {1.0, 2.0, 4.0}) {
    const Scene whole_scene = canyon(h_over_w);
    const Renderer whole(whole_scene);
    const double h = h_over_w * kWidth;
    for (double strip : {1.0, 0.1}) {
      const Scene strips_scene = canyon(h_over_w, strip);
      const Renderer strips(strips_scene);
      for (double share : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        const Ray ray{Vec3{0.05, -kWidth / 2 + 0.3, share * h}, {0, -1, 0}};
        const double expected = luminance(whole.radiance(ray)), got = luminance(strips.radiance(ray));
        EXPECT_NEAR(got / expected, 1.0, 0.01) << "h/w " << h_over_w << ", strips " << strip << " m, " << share;
      }
    }
  }
}

TEST(CanyonLight, TheSceneChoosesWhatLightsTheObstacles) {
  testing::TempDir dir;
  const auto scene_file = dir.write("scene.json", testing::small_scene_json());
  EXPECT_TRUE(load_scene(scene_file).render.obstacles_own_sky);  // the default: physically right
  EXPECT_TRUE(load_scene(scene_file, {"render.obstacle_light=own_sky"}).render.obstacles_own_sky);
  EXPECT_FALSE(load_scene(scene_file, {"render.obstacle_light=open_sky"}).render.obstacles_own_sky);
  const std::string error = testing::input_error_of([&] { load_scene(scene_file, {"render.obstacle_light=closed"}); });
  EXPECT_NE(error.find("render.obstacle_light"), std::string::npos) << error;
}

}  // namespace
}  // namespace skylit
