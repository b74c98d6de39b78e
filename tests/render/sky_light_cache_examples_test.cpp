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
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "skylit/compare/region_comparison.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/renderer.h"
#include "skylit/render/surface_cache.h"
#include "skylit/sky/sky_light.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

struct CacheDeviation {
  double p99 = 0, mean_ratio = 0;
  size_t pixels = 0;
  // Against a converged quadrature (kConvergedDirections), when asked for: the cached
  // value's 99th percentile and the exact value's own (its 1024 directions' error).
  double cached_converged_p99 = 0, exact_converged_p99 = 0;
};

// Directions of the converged sky light: 16 times the renderer's 1024.
constexpr int kConvergedDirections = 16384;

// Every `stride`-th pixel centre in both directions (offset so that most are not grid
// points themselves): |cached / exact − 1| of the diffuse sky light's illuminance.
CacheDeviation cache_deviation(const std::string& example, int width, int height, int stride,
                               bool against_converged = false) {
  const Scene scene = load_scene(std::string(SKYLIT_SOURCE_DIR) + "/examples/" + example,
                                 {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)});
  const Renderer renderer(scene);
  const BandsIntegrator& integrator = renderer.bands();
  const ImageCamera camera(scene.camera, width, height);
  const PrimaryHits hits(camera, width, height, [&](const Ray& ray) { return integrator.first_hit(ray); });
  auto diffuse = [&](const SurfacePoint& p) {
    CachedSkyLight value;
    value.diffuse_irradiance =
        integrator.sky_light().diffuse_irradiance(p.position, p.normal, &value.obstacle_distance_m);
    return value;
  };
  const SurfaceCache cache(hits, [&](const SurfacePoint& p, int, int) { return diffuse(p); });
  const std::unique_ptr<SkyLight> converged =
      against_converged ? integrator.sky_light_with(kConvergedDirections) : nullptr;
  const int rows = (height - 1) / stride + 1;
  std::vector<std::vector<double>> ratios(static_cast<size_t>(rows));
  // |cached / converged − 1| and |exact / converged − 1| per pixel, by row.
  std::vector<std::vector<std::pair<double, double>>> off_converged(static_cast<size_t>(rows));
  tbb::parallel_for(0, rows, [&](int row) {
    const int y = std::min(row * stride + stride / 2, height - 1);
    for (int x = stride / 2; x < width; x += stride) {
      const SurfacePoint* point = hits.surface(x, y);
      if (!point || !camera.sees(x + 0.5, y + 0.5)) continue;
      const std::optional<CachedSkyLight> cached = cache.interpolate(x + 0.5, y + 0.5, *point);
      if (!cached) continue;  // the renderer computes such a sample itself
      const double exact = illuminance(diffuse(*point).diffuse_irradiance);
      if (!(exact > 0)) continue;
      const double cached_lx = illuminance(cached->diffuse_irradiance);
      ratios[static_cast<size_t>(row)].push_back(cached_lx / exact);
      if (!converged) continue;
      const double truth = illuminance(converged->diffuse_irradiance(point->position, point->normal));
      if (truth > 0)
        off_converged[static_cast<size_t>(row)].emplace_back(std::abs(cached_lx / truth - 1),
                                                             std::abs(exact / truth - 1));
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
  if (converged) {
    std::vector<double> cached_off, exact_off;
    for (const auto& row : off_converged)
      for (const auto& [c, e] : row) {
        cached_off.push_back(c);
        exact_off.push_back(e);
      }
    result.cached_converged_p99 = quantile(cached_off, 0.99);
    result.exact_converged_p99 = quantile(exact_off, 0.99);
    std::printf("  against %d directions: cached 99th percentile %.4f, exact (1024) %.4f\n", kConvergedDirections,
                result.cached_converged_p99, result.exact_converged_p99);
  }
  std::printf(
      "%s %d×%d (every %d px, %zu pixels; cache %d coarse, %d fine, %d per-pixel points): mean ratio %.4f, "
      "99th percentile %.4f, worst %.4f\n",
      example.c_str(), width, height, stride, result.pixels, cache.coarse_points(), cache.fine_points(),
      cache.pixel_points(), result.mean_ratio, result.p99, deviations.back());
  return result;
}

// Bound on the 99th percentile of the per-pixel deviation: the 2 %. The exact
// value and the cached one come from the same quadrature, so the deviation is the
// cache's against its own points; the 1024-direction integral is itself off the
// converged sky light by about as much (next test), in steps as obstacle edges cross its
// directions, which no smooth interpolation follows. History (every 2nd pixel unless
// said): 27.7 % and 25.8 % at 320 × 180 and 480 × 270 before corners were refused at
// all; 9.2 % and 7.2 % with the corners' sky light compared; 5.2 % and 5.4 % with
// corners kept within their obstacles' reach (2026-12-03, cache_corner_agreement.h);
// with the obstacles lit by their own sky and the corners' 15 % spread (2026-12-04):
// 4.3 % and 5.3 %; with the cells' means (2026-12-05, sky/sky_light.h): 3.1 % and 4.9 %;
// with a lone corner kept within its obstacles' reach 2.3 % and 3.4 %, then refused on
// the grids 2.1 % and 2.0 %; with every cell checked at its middle (2026-12-07,
// SurfaceCache::check_cells) 1.65 % and 1.72 % (every pixel: 1.57 % and 1.66 %). The
// bound leaves Fig. 7 0.3 point; the default example, which the heavy test below holds to
// it as well, 0.07 point at 320 × 180.
constexpr double kTolerance = 0.02;

TEST(SkyLightCacheExamples, Fig7AtSmallSizesStaysNearTheExactSkyLight) {
  for (const auto& [width, height] : {std::pair{320, 180}, std::pair{480, 270}}) {
    const CacheDeviation d = cache_deviation("fig7.json", width, height, 2);
    ASSERT_GT(d.pixels, 5000u);
    EXPECT_LT(d.p99, kTolerance) << width << "×" << height;
  }
}

// Against the converged sky light (16,384 directions), the cache's 99th percentile
// stays within 2 points of the 1024-direction integral's own: what the cache adds to
// the quadrature's error. Measured (2026-12-03, every 4th pixel, Fig. 7 at 320 × 180):
// cached 4.81 %, the integral itself 3.46 % (quantile()'s interpolated 99th percentile;
// 4.96 % and 3.47 % by the nearest rank, as docs/sky-light.md quotes); 12.3 % before
// corners were kept within their obstacles' reach. With the obstacles' own sky
// (2026-12-04): 5.47 % and 3.44 % with the 20 % spread (over the bound), 5.23 % with
// 15 %. Every 2nd pixel since 2026-12-05 (at every 4th the 99th percentile of 1,273
// pixels moved by a quarter point with the pixels taken): 3.55 % and 3.36 % with the
// sky model's table and the elements' centres; 2.84 % and 1.81 % with the cells' means
// (sky/sky_light.h; the converged value built the same way); 2.88 % and 1.47 % with
// the outlines across sub-cells bisected; 2.19 % and 1.47 % with a lone corner kept
// within its obstacles' reach; 1.94 % and 1.34 % with the outlines that matter traced
// apart (2026-12-07); 1.22 % and 1.34 % with every cell checked at its middle (later
// that day): the cache now nearer the converged value than its own points are. 4 s.
TEST(SkyLightCacheExamples, Fig7CacheAddsLittleToTheQuadraturesOwnError) {
  const CacheDeviation d = cache_deviation("fig7.json", 320, 180, 2, true);
  ASSERT_GT(d.pixels, 4000u);
  EXPECT_GT(d.exact_converged_p99, 0.01);  // the quadrature's steps do show
  EXPECT_LT(d.cached_converged_p99, d.exact_converged_p99 + 0.02);
}

// The house's front door and windows sit 12 cm back in their reveals. At 320 × 180 a
// coarse cell with a single corner on the door (at its edge, 18 % darker than the
// middle: the reveal hides part of the sky) gave its value to every door pixel within
// 5 % of the camera's distance: a half-disc of the door 13–20 % too dark. A lone
// corner was then let stand in only within its obstacles' reach (2026-12-05).
// Measured (every pixel): 99th percentile 19.2 % before, 11.7 %
// after; the rest is the window frames and sills a pixel wide, which the heavy test
// below bounds too. A sliver's nearest grid point kept within its obstacles' reach as
// well (2026-12-06): 11.2 → 10.3 %, the worst pixel 4.77 → 0.82 of the exact value
// off (the roof's edge had taken a point's value from beside a standing seam). A lone
// corner no longer stands in at all on the grids (later that day): 10.0 → 7.2 % (the
// wall under the eaves had taken a corner's value from lower down, 10–20 % too bright;
// what is left is mostly the pixels beside frames, sills and the roof's seams). Every
// cell checked at its middle (2026-12-07): 7.6 → 5.4 %, what is left the pixels whose
// centres fall within a few centimetres of the roof's standing seams (each hides a
// share of the sky there, a dotted line along each seam) and the 1,024-direction
// integral's own scatter on the lawn beside the house (against 16,384 directions the
// exact value's 99th percentile is 2.0 %, the cached one's 4.7 %). The bound leaves 1
// point. 3 s.
TEST(SkyLightCacheExamples, ALoneCornerDoesNotStandInAcrossARecess) {
  const CacheDeviation d = cache_deviation("house.json", 320, 180, 1);
  ASSERT_GT(d.pixels, 5000u);
  EXPECT_LT(d.p99, 0.065);
}

TEST(SkyLightCacheExamples, ExamplesAtAllSizesStayNearTheExactSkyLight) {
  if (!std::getenv("SKYLIT_SKY_LIGHT_ACCURACY")) GTEST_SKIP() << "heavy: set SKYLIT_SKY_LIGHT_ACCURACY=1";
  // Measured 2026-12-03 (99th percentile; 1920 × 1080 every 4th pixel): Fig. 7 4.7 %,
  // 4.8 %, 4.7 % at 320 × 180, 480 × 270, 1920 × 1080; building 4.3 %, 4.8 %, 3.7 %;
  // house 18.3 %, 15.7 %, 14.8 % (its window frames and roof facets a pixel wide, as in
  // sky_light_accuracy_test.cpp). Before corners were kept within their obstacles'
  // reach: Fig. 7 7.9 %, 5.4 %, 7.1 %; building 14.2 %, 14.7 %, 3.7 %; house the same.
  // 2026-12-05 (obstacles lit by their own sky, the cells' means, the outlines
  // bisected): Fig. 7 3.1 %, 3.9 %, 2.5 %; building 3.8 %, 3.8 %, 3.4 %; house
  // 19.2 %, 17.1 %, 15.4 % (docs/sky-light.md has what refusing more cells would give).
  // 2026-12-05 (a lone corner within its obstacles' reach): Fig. 7 2.3 %, 3.0 %, 2.4 %;
  // building 3.0 %, 3.4 %, 3.0 %; house 11.7 %, 13.1 %, 13.8 % (the rest its pixel-wide
  // frames and sills). 2026-12-06 (deep cells' corners within 1 %, a sliver's nearest
  // point within its obstacles' reach): Fig. 7 2.2 %, 2.0 %, 2.3 %; building 2.7 %,
  // 3.2 %, 2.7 %; house 10.0 %, 11.8 %, 12.5 %. Later that day (a lone corner refused on
  // the grids): Fig. 7 2.0 %, 1.9 %, 2.3 %; building 2.4 %, 3.1 %, 2.7 %; house 7.2 %,
  // 9.4 %, 12.0 % (at 1920 × 1080 mostly cells with two corners on the glass, frames and
  // sills, docs/sky-light.md). 2026-12-07 (the outlines that matter traced apart, the
  // obstacles' directions turned): Fig. 7 2.0 %, 1.9 %, 2.2 %; building 2.5 %, 3.2 %,
  // 2.9 %; house 7.4 %, 9.7 %, 12.3 %. Later that day (every cell checked at its
  // middle, SurfaceCache::check_cells): Fig. 7 1.57 %, 1.66 %, 1.39 %; building 1.93 %,
  // 1.75 %, 1.45 %; house 5.4 %, 6.4 %, 4.1 % (the pixels beside the roof's seams and the
  // integral's own scatter beside the house, above). 65 s.
  for (const auto& [example, bound] :
       {std::pair{"fig7.json", kTolerance}, std::pair{"building.json", kTolerance}, std::pair{"house.json", 0.075}})
    for (const auto& [width, height] : {std::pair{320, 180}, std::pair{480, 270}, std::pair{1920, 1080}}) {
      const CacheDeviation d = cache_deviation(example, width, height, width > 1000 ? 4 : 1);
      ASSERT_GT(d.pixels, 5000u);
      EXPECT_LT(d.p99, bound) << example << " " << width << "×" << height;
    }
}

}  // namespace
}  // namespace skylit
