// The sky-light cache (render/surface_cache.h) against the exact sky light on the
// examples, at several image sizes (issue 14 item 3): at small sizes one cache cell near
// the horizon spans tens of metres of the ground, and interpolating across it mixed
// points beside buildings with open ground. Compared per pixel centre: the illuminance
// of the cached diffuse sky light against the same quantity computed exactly there
// (SkyLight::diffuse_irradiance, 1024 directions), so the comparison isolates the cache.
// Fig. 7 at 320 × 180 and 480 × 270 run always (a few seconds); 1920 × 1080 and the other
// examples with SKYLIT_SKY_LIGHT_ACCURACY=1 (minutes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/renderer.h"
#include "skylit/render/surface_cache.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

struct CacheDeviation {
  double p99 = 0, mean_ratio = 0;
  size_t pixels = 0;
};

// Every `stride`-th pixel centre in both directions (offset so that most are not grid
// points themselves): |cached / exact − 1| of the diffuse sky light's illuminance.
CacheDeviation cache_deviation(const std::string& example, int width, int height, int stride) {
  const Scene scene = load_scene(std::string(SKYLIT_SOURCE_DIR) + "/examples/" + example,
                                 {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)});
  const Renderer renderer(scene);
  const BandsIntegrator& integrator = renderer.bands();
  const ImageCamera camera(scene.camera, width, height);
  const PrimaryHits hits(camera, width, height, [&](const Ray& ray) { return integrator.first_hit(ray); });
  auto diffuse = [&](const SurfacePoint& p) {
    return CachedSkyLight{integrator.sky_light().diffuse_irradiance(p.position, p.normal), Radiance(0.0f)};
  };
  const SurfaceCache cache(hits, diffuse);
  const int rows = (height - 1) / stride + 1;
  std::vector<std::vector<double>> ratios(static_cast<size_t>(rows));
  tbb::parallel_for(0, rows, [&](int row) {
    const int y = std::min(row * stride + stride / 2, height - 1);
    for (int x = stride / 2; x < width; x += stride) {
      const SurfacePoint* point = hits.surface(x, y);
      if (!point || !camera.sees(x + 0.5, y + 0.5)) continue;
      const std::optional<CachedSkyLight> cached = cache.interpolate(x + 0.5, y + 0.5, *point);
      if (!cached) continue;  // the renderer computes such a sample itself
      const double exact = illuminance(diffuse(*point).diffuse_irradiance);
      if (exact > 0) ratios[static_cast<size_t>(row)].push_back(illuminance(cached->diffuse_irradiance) / exact);
    }
  });
  std::vector<double> deviations;
  CacheDeviation result;
  for (const auto& row : ratios)
    for (const double r : row) {
      deviations.push_back(std::abs(r - 1));
      result.mean_ratio += r;
    }
  result.pixels = deviations.size();
  if (deviations.empty()) return result;
  result.mean_ratio /= static_cast<double>(deviations.size());
  std::sort(deviations.begin(), deviations.end());
  result.p99 = deviations[deviations.size() * 99 / 100];
  std::printf(
      "%s %d×%d (every %d px, %zu pixels; cache %d coarse, %d fine, %d per-pixel points): mean ratio %.4f, "
      "99th percentile %.4f, worst %.4f\n",
      example.c_str(), width, height, stride, result.pixels, cache.coarse_points(), cache.fine_points(),
      cache.pixel_points(), result.mean_ratio, result.p99, deviations.back());
  return result;
}

// Bound on the 99th percentile of the per-pixel deviation. The issue asks for 2 %; the
// cache does not reach it at a cost the frame budget allows (docs/sky-light.md): on
// Fig. 7 it measured (2026-12-02, every 2nd pixel) 9.0 % at 320 × 180 and 6.9 % at
// 480 × 270, against 27.7 % and 25.8 % before corners were refused (a cell's corners
// then stood in for any point of their plane). The bound leaves that a margin and fails
// by a factor two on the old cache. The exact value and the cached one come from the
// same 1024-direction quadrature, so the deviation is the cache's alone.
constexpr double kTolerance = 0.12;

TEST(SkyLightCacheExamples, Fig7AtSmallSizesStaysNearTheExactSkyLight) {
  for (const auto& [width, height] : {std::pair{320, 180}, std::pair{480, 270}}) {
    const CacheDeviation d = cache_deviation("fig7.json", width, height, 2);
    ASSERT_GT(d.pixels, 5000u);
    EXPECT_LT(d.p99, kTolerance) << width << "×" << height;
  }
}

TEST(SkyLightCacheExamples, ExamplesAtAllSizesStayNearTheExactSkyLight) {
  if (!std::getenv("SKYLIT_SKY_LIGHT_ACCURACY")) GTEST_SKIP() << "heavy: set SKYLIT_SKY_LIGHT_ACCURACY=1";
  // Measured 2026-12-02 (99th percentile; 1920 × 1080 every 4th pixel): Fig. 7 7.9 %,
  // 5.4 %, 7.1 % at 320 × 180, 480 × 270, 1920 × 1080; building 14.2 %, 14.7 %, 3.7 %;
  // house 18.2 %, 15.6 %, 14.8 % (its window frames and roof facets a pixel wide, as in
  // sky_light_accuracy_test.cpp). Neither reaches the 2 %; the other examples'
  // bound only catches a cache gone wrong.
  for (const auto& [example, bound] :
       {std::pair{"fig7.json", kTolerance}, std::pair{"building.json", 0.25}, std::pair{"house.json", 0.25}})
    for (const auto& [width, height] : {std::pair{320, 180}, std::pair{480, 270}, std::pair{1920, 1080}}) {
      const CacheDeviation d = cache_deviation(example, width, height, width > 1000 ? 4 : 1);
      ASSERT_GT(d.pixels, 5000u);
      EXPECT_LT(d.p99, bound) << example << " " << width << "×" << height;
    }
}

}  // namespace
}  // namespace skylit
