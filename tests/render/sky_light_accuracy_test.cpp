// The sky-light cache (render/surface_cache.h) and the fewer directions of sliver samples
// (BandsIntegrator::kOnePixelDirections) against the exact sky light at every sample, on a
// dense model: 8 × 8 copies of examples/models/house.obj (886 triangles, 7 materials
// each) seen from afar at 320 × 180, where nearly every pixel is an edge. Heavy (the
// exact image takes about a minute here): run with SKYLIT_SKY_LIGHT_ACCURACY=1;
// SKYLIT_SKY_LIGHT_ACCURACY_SCENE=FILE measures another scene and prints its figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../test_support.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/renderer.h"

namespace skylit {
namespace {

std::string dense_houses_scene(int grid) {
  const std::string model = std::string(SKYLIT_SOURCE_DIR) + "/examples/models/house.obj";
  std::string objects = R"({"name": "ground", "type": "plane", "material": "lawn", "size_m": 4000})";
  std::string names;
  for (int i = 0; i < grid * grid; ++i) {
    const std::string name = "house" + std::to_string(i);
    objects += R"(, {"name": ")" + name + R"(", "type": "mesh", "file": ")" + model +
               R"(", "transform": {"translate": [)" + std::to_string(20 * (i % grid)) + ", " +
               std::to_string(20 * (i / grid)) + ", 0]}}";
    names += std::string(i ? ", " : "") + '"' + name + '"';
  }
  return R"({"camera": {"frame": [)" + names + R"(], "from_azimuth_deg": 225, "elevation_deg": 25},
    "sun": {"altitude_deg": 35, "azimuth_deg": 200}, "materials": {"lawn": "grass"},
    "objects": [)" +
         objects + R"(], "render": {"width": 320, "height": 180}})";
}

TEST(SkyLightAccuracy, CacheAndSliverSamplesStayCloseToTheExactSkyLight) {
  if (!std::getenv("SKYLIT_SKY_LIGHT_ACCURACY")) GTEST_SKIP() << "heavy: set SKYLIT_SKY_LIGHT_ACCURACY=1";
  testing::TempDir dir;
  const char* other = std::getenv("SKYLIT_SKY_LIGHT_ACCURACY_SCENE");
  const Scene scene = other ? load_scene(other, {"render.width=320", "render.height=180"})
                            : load_scene(dir.write("houses.json", dense_houses_scene(8)));
  const Renderer renderer(scene);
  RenderOptions exact;
  exact.exact_sky_light = true;
  const XyzImage fast_image = renderer.render(), exact_image = renderer.render(exact);
  // Per pixel: the luminance ratio fast / exact.
  std::vector<double> ratios, deviations;
  for (int y = 0; y < fast_image.height; ++y)
    for (int x = 0; x < fast_image.width; ++x) {
      const double e = exact_image.at(x, y).y, f = fast_image.at(x, y).y;
      if (!(e > 0)) continue;
      ratios.push_back(f / e);
      deviations.push_back(std::abs(f / e - 1));
    }
  ASSERT_GT(ratios.size(), 1000u);
  double mean = 0;
  for (double r : ratios) mean += r / static_cast<double>(ratios.size());
  std::sort(deviations.begin(), deviations.end());
  const double p99 = deviations[deviations.size() * 99 / 100];
  const auto beyond = std::count_if(deviations.begin(), deviations.end(), [](double d) { return d > 0.05; });
  std::printf("mean ratio %.5f, 99th percentile %.4f, beyond 5 %%: %.2f %%\n", mean, p99,
              100.0 * static_cast<double>(beyond) / static_cast<double>(deviations.size()));
  // Measured on these 64 houses (2026-12-02): with sliver samples from all 1024
  // directions (the cache's own error) mean ratio 1.00288, 99th percentile 17.5 %, 4.0 %
  // of pixels beyond 5 %; with kOnePixelDirections the same to 1e-4. The errors are the
  // cache's: sky light taken from a neighbouring point of the same material and plane
  // (window frames and roof facets a pixel wide). The bounds leave those a margin of
  // 2.5 points; a systematic error (a wrong direction set, a misplaced look-up) moves
  // the mean by percents. 2026-12-06, with the one-pixel level, the tiles' sliver values
  // and a lone cache corner refused on the grids: mean ratio 1.00061, 99th percentile
  // 6.06 %, 1.22 % of pixels beyond 5 % (8.5 % and 1.66 % the day before); the bound
  // keeps the 2.5 points.
  EXPECT_NEAR(mean, 1.0, 0.005);
  EXPECT_LT(p99, 0.085);
}

}  // namespace
}  // namespace skylit
