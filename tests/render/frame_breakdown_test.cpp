// A frame's breakdown (render/frame_breakdown.h): the sky-light cache's counts against
// its grids' geometry, the parts' times against the frame's own, and the obstacle
// patches by the obstacle light asked for.
#include "skylit/render/frame_breakdown.h"

#include <gtest/gtest.h>

#include <chrono>

#include "skylit/geometry/primitives.h"
#include "skylit/render/renderer.h"

namespace skylit {
namespace {

// Looking straight down on a ground plane that fills the view, with a box on it.
Scene box_on_a_plane(int width, int height) {
  Scene scene;
  scene.camera = Camera{{0, 0, 60}, {0, 0.001, 0}, {0, 1, 0}, 40.0};
  scene.sun = Sun{40, 200};
  scene.materials.push_back({"grey", DiffuseMaterial{Spectrum(0.4f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 1000), 0});
  scene.objects.push_back({"box", make_box({-4, -4, 0}, {4, 4, 12}), 0});
  scene.render = RenderSettings{width, height, std::nullopt, 1};
  return scene;
}

TEST(FrameBreakdown, CountsTheCoarseGridAndTimesTheFrame) {
  const Scene scene = box_on_a_plane(65, 49);
  const Renderer renderer(scene);
  FrameBreakdown frame;
  RenderOptions options;
  options.breakdown = &frame;
  const auto start = std::chrono::steady_clock::now();
  renderer.render(options);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Every pixel sees a surface: the 16-pixel grid's points at pixels 0, 16, 32, 48 and 64
  // across and 0, 16, 32 and 48 down are all computed.
  EXPECT_EQ(frame.coarse_points, 5 * 4);
  // The box's walls and its foot need the finer levels.
  EXPECT_GT(frame.fine_points + frame.pixel_points, 0);
  // The parts follow each other inside the render call; one sample a pixel: no second pass.
  for (double part : {frame.primary_hits_s, frame.caches_s, frame.centres_pass_s}) EXPECT_GT(part, 0.0);
  EXPECT_EQ(frame.edges_pass_s, 0.0);
  EXPECT_LE(frame.primary_hits_s + frame.caches_s + frame.centres_pass_s, wall_s);
  // The box's walls and the ground around it light each other: patches at both levels.
  ASSERT_EQ(frame.obstacle_patches.size(), 2u);
  EXPECT_GT(frame.obstacle_patches[0], 0u);
  const std::string line = describe(frame);
  EXPECT_NE(line.find("20 + " + std::to_string(frame.fine_points) + " grid points"), std::string::npos) << line;
  EXPECT_NE(line.find("obstacle patches"), std::string::npos) << line;
}

TEST(FrameBreakdown, NoCacheNoPatchesWhereNoneIsAskedFor) {
  Scene scene = box_on_a_plane(33, 25);
  scene.render.obstacles_own_sky = false;  // the obstacles lit by the open sky: no patches
  const Renderer renderer(scene);
  // Left from another frame: the render replaces all of it.
  FrameBreakdown frame{1, 1, 1, 1, 5, 5, 5, 1, 5, {7, 7}};
  RenderOptions options;
  options.breakdown = &frame;
  options.exact_sky_light = true;  // every sample its own integral: no cache
  renderer.render(options);
  EXPECT_EQ(frame.edges_pass_s, 0.0);
  EXPECT_EQ(frame.coarse_points + frame.fine_points + frame.cell_checks + frame.pixel_points, 0);
  EXPECT_TRUE(frame.obstacle_patches.empty());
  EXPECT_EQ(describe(frame).find("obstacle patches"), std::string::npos);
}

}  // namespace
}  // namespace skylit
