// The sky-light cache on surfaces broken into pieces smaller than its grids (a model of
// many small parts seen from afar): every pixel centre still gets a value of its own
// surface from the cache, and the antialiasing samples inside a pixel share it instead
// of each needing an exact computation.
#include "skylit/render/surface_cache.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "skylit/render/camera.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

constexpr int kWidth = 64, kHeight = 48;

// A camera 100 m above the plane z = 0, looking straight down (or `camera_setup`); the
// plane's material changes every `tile_m` metres in x and y among `materials` materials.
PrimaryHits hits_of_tiled_plane(double tile_m, int materials,
                                const Camera& camera_setup = Camera{{0, 0, 100}, {0, 0, 0}, {0, 1, 0}, 50.0}) {
  const ImageCamera camera(camera_setup, kWidth, kHeight);
  return PrimaryHits(camera, kWidth, kHeight, [&](const Ray& ray) {
    const double t = -ray.origin.z / ray.direction.z;
    const Vec3 p = ray.origin + t * ray.direction;
    const auto ix = static_cast<long>(std::floor(p.x / tile_m)), iy = static_cast<long>(std::floor(p.y / tile_m));
    const auto material = static_cast<uint32_t>(((ix * 7 + iy * 13) % materials + materials) % materials);
    return PrimaryHit{0, SurfacePoint{p, {0, 0, 1}, t, material}};
  });
}

// A value that differs from point to point, so a look-up shows which point it came from.
CachedSkyLight value_at(const SurfacePoint& p, int = 0, int = 0) {
  return {Irradiance(static_cast<float>(1000 + p.position.x + 0.01 * p.position.y)), Radiance(0.0f)};
}

TEST(SurfaceCache, PixelsOfSurfacesSmallerThanTheGridsGetTheirCentresValue) {
  // Tiles of about one pixel (the footprint is 2·100·tan 25° / 48 ≈ 1.94 m) among 64
  // materials: the coarse and fine grids cover almost nothing.
  const PrimaryHits hits = hits_of_tiled_plane(1.9, 64);
  std::atomic<int> computed{0};
  const SurfaceCache cache(hits, [&](const SurfacePoint& p, int, int) {
    ++computed;
    return value_at(p);
  });
  EXPECT_GT(cache.pixel_points(), kWidth * kHeight / 2);
  EXPECT_EQ(computed.load(), cache.coarse_points() + cache.fine_points() + cache.pixel_points());
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const SurfacePoint& centre = *hits.surface(x, y);
      const std::optional<CachedSkyLight> at_centre = cache.interpolate(x + 0.5, y + 0.5, centre);
      ASSERT_TRUE(at_centre) << x << ", " << y;
      // A sample a quarter pixel away on the centre's surface (the same material and
      // plane) gets a value of that surface: from its own centre or another point of the
      // same material on the plane, as the cache's same_surface allows, within one
      // coarse cell (16 px ≈ 31 m, so value_at differs by at most ≈ 31.4).
      SurfacePoint sample = centre;
      sample.position += Vec3{0.4, 0.4, 0};
      const std::optional<CachedSkyLight> at_sample = cache.interpolate(x + 0.75, y + 0.75, sample);
      ASSERT_TRUE(at_sample) << x << ", " << y;
      EXPECT_NEAR(at_sample->diffuse_irradiance[0], value_at(centre).diffuse_irradiance[0], 32.0f);
    }
  // The centres that no grid covers are computed exactly at that centre: the value is
  // the centre's own (the other corners of its cell, on other tiles, do not count, or
  // with the 1e-3 weight floor when they share its tile: at most 1e-3 · 4 off).
  int own = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const SurfacePoint& centre = *hits.surface(x, y);
      const float expected = value_at(centre).diffuse_irradiance[0];
      if (std::abs(cache.interpolate(x + 0.5, y + 0.5, centre)->diffuse_irradiance[0] - expected) < 0.02f) ++own;
    }
  EXPECT_GE(own, cache.pixel_points());
  // A surface that no pixel centre sees has no value: the caller computes it exactly.
  SurfacePoint elsewhere = *hits.surface(10, 10);
  elsewhere.material = 1000;
  EXPECT_FALSE(cache.interpolate(10.5, 10.5, elsewhere));
}

TEST(SurfaceCache, NoPixelIsComputedTwiceByTheSameIntegral) {
  // Tiles of about one pixel: the fine grid and the pixel centres are wanted nearly
  // everywhere, at the coarse and fine points' pixels too, which take those points'
  // values instead of their own (until 2026-12-08 they computed them again: 1 in 16 of
  // the fine points) where the level computes them the same way.
  const PrimaryHits hits = hits_of_tiled_plane(1.9, 64);
  std::vector<std::atomic<int>> full(kWidth * kHeight), one_pixel(kWidth * kHeight);
  auto counted = [&](std::vector<std::atomic<int>>& count) {
    return [&](const SurfacePoint& p, int x, int y) {
      ++count[static_cast<size_t>(y * kWidth + x)];
      return value_at(p);
    };
  };
  auto total = [](const std::vector<std::atomic<int>>& count) {
    int sum = 0;
    for (const std::atomic<int>& n : count) {
      EXPECT_LE(n.load(), 1);
      sum += n.load();
    }
    return sum;
  };
  // One integral for every level: no pixel twice.
  const SurfaceCache one_integral(hits, counted(full));
  EXPECT_EQ(total(full), one_integral.coarse_points() + one_integral.fine_points() + one_integral.pixel_points());
  // A coarser one for the pixel centres: each integral at most once at a pixel, and the
  // pixel centres at the grids' points computed with theirs (a value of more directions
  // would stand out among its neighbours).
  for (std::atomic<int>& n : full) n = 0;
  const SurfaceCache two_integrals(hits, counted(full), counted(one_pixel));
  const int computed_full = total(full), computed_one_pixel = total(one_pixel);
  EXPECT_EQ(computed_full + computed_one_pixel,
            two_integrals.coarse_points() + two_integrals.fine_points() + two_integrals.pixel_points());
  EXPECT_GT(one_pixel[0].load(), 0);  // the coarse point at (0, 0) is on a tile of its own
}

TEST(SurfaceCache, OneLargeSurfaceNeedsNoPerPixelPoints) {
  // One material over the whole view: the coarse grid covers every pixel.
  const PrimaryHits hits = hits_of_tiled_plane(1000.0, 1);
  const SurfaceCache cache(hits, value_at);
  EXPECT_EQ(cache.fine_points(), 0);
  EXPECT_EQ(cache.pixel_points(), 0);
  // No obstacles (value_at's are infinitely far): no cell needs its check.
  EXPECT_EQ(cache.cell_checks(), 0);
  const SurfacePoint& p = *hits.surface(20, 30);
  ASSERT_TRUE(cache.interpolate(20.5, 30.5, p));
}

TEST(SurfaceCache, ADipBetweenCornersThatAgreeIsFoundByTheCellsCheck) {
  // The sky light dips by 20 % over a few metres around the middle of one coarse cell
  // (pixel 24, 24; its corners 16 pixels ≈ 31 m away agree to 1e-6), as it does beside
  // a sill or in a recess, its obstacles 20 m from every point: the cell's blend there
  // would be 1.25 times the value. The check at the middle fails the cell, and the pixel
  // gets the finer levels' value.
  const PrimaryHits hits = hits_of_tiled_plane(1e5, 1);
  const Vec3 dip = hits.surface(24, 24)->position;
  const auto dipped = [&](const SurfacePoint& p, int, int) {
    CachedSkyLight v = value_at(p);
    const double d_m = length(p.position - dip);
    v.diffuse_irradiance = Irradiance(static_cast<float>(1000 * (1 - 0.2 * std::exp(-d_m * d_m / 9))));
    v.obstacle_distance_m = 20;
    return v;
  };
  std::atomic<int> computed{0};
  const SurfaceCache cache(hits, [&](const SurfacePoint& p, int x, int y) {
    ++computed;
    return dipped(p, x, y);
  });
  // Each point once: a check's point is kept by its level, not computed again.
  EXPECT_EQ(computed.load(), cache.coarse_points() + cache.fine_points() + cache.pixel_points());
  const SurfacePoint& middle = *hits.surface(24, 24);
  const std::optional<CachedSkyLight> at_middle = cache.interpolate(24.5, 24.5, middle);
  ASSERT_TRUE(at_middle);
  EXPECT_NEAR(at_middle->diffuse_irradiance[0], dipped(middle, 24, 24).diffuse_irradiance[0], 1.0f);
  // Only around the dip: the other coarse cells pass and cover their pixels.
  EXPECT_GT(cache.fine_points() + cache.pixel_points(), cache.cell_checks());
  EXPECT_LT(cache.fine_points(), 2 * 25 + cache.cell_checks());
  // Without the dip, its obstacles as near: every cell is checked and passes.
  const SurfaceCache flat(hits, [](const SurfacePoint& p, int, int) {
    CachedSkyLight v = value_at(p);
    v.diffuse_irradiance = Irradiance(1000.0f);
    v.obstacle_distance_m = 20;
    return v;
  });
  EXPECT_GT(flat.cell_checks(), 0);
  EXPECT_EQ(flat.fine_points() + flat.pixel_points(), flat.cell_checks());
  // Obstacles 2 km away: the sky light cannot dip within a 31 m cell, and no cell is
  // checked (kSmoothReach).
  const SurfaceCache far(hits, value_at);
  EXPECT_EQ(far.cell_checks(), 0);
}

TEST(SurfaceCache, APixelBetweenNeighboursThatAgreeTakesTheirMeanAndOneAcrossAStepItsOwn) {
  // The sky light steps up by 5 % between pixel rows 18 and 19 of a plane seen straight
  // down (a shadow's edge in the sky light, its obstacles 20 m from every point), and
  // rises by 0.01 % a row elsewhere. The grids' cells across the step fail their checks
  // (their blends are 2.5 % off at their middles); the per-pixel level computes every
  // other pixel there, and the rest from their neighbours above and below where those
  // agree within kCloseSpread: exactly for a linear rise, never across the step.
  const PrimaryHits hits = hits_of_tiled_plane(1e5, 1);
  const auto stepped = [](int y) { return 1000.0 * (1 + 1e-4 * y) * (y >= 19 ? 1.05 : 1.0); };
  std::atomic<int> computed{0};
  const SurfaceCache cache(hits, [&](const SurfacePoint& p, int, int y) {
    ++computed;
    CachedSkyLight v = value_at(p);
    v.diffuse_irradiance = Irradiance(static_cast<float>(stepped(y)));
    v.obstacle_distance_m = 20;
    return v;
  });
  EXPECT_EQ(computed.load(), cache.coarse_points() + cache.fine_points() + cache.pixel_points());
  EXPECT_GT(cache.pixels_between(), 0);
  EXPECT_GT(cache.pixel_points(), 0);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::optional<CachedSkyLight> v = cache.interpolate(x + 0.5, y + 0.5, *hits.surface(x, y));
      ASSERT_TRUE(v) << x << ", " << y;
      // Half the step (2.5 %) where a value were blended across it; float rounding else.
      EXPECT_NEAR(v->diffuse_irradiance[0], stepped(y), 1e-4 * stepped(y)) << x << ", " << y;
    }
}

// Ground seen at a grazing angle from 3 m up.
const Camera kGrazing{{0, 0, 3}, {0, 60, 0}, {0, 0, 1}, 50.0};

// A value 1000 + `per_m` · y (changing along the grazing view), its obstacles `obstacle_m`
// away.
SurfaceCache::Compute sloped(double per_m, double obstacle_m) {
  return [per_m, obstacle_m](const SurfacePoint& p, int, int) {
    CachedSkyLight v = value_at(p);
    v.diffuse_irradiance = Irradiance(static_cast<float>(1000 + per_m * p.position.y));
    v.obstacle_distance_m = obstacle_m;
    return v;
  };
}

// Points a cache computed on its finer levels, checks of its cells (SurfaceCache::check_cells) included.
int finer_points(const SurfaceCache& cache) { return cache.fine_points() + cache.pixel_points(); }

// `checked` refined no more than `unchecked` but for its cells' checks (a check's point
// may also be one the refinement wants, so it is not simply the sum).
void expect_refined_alike(const SurfaceCache& checked, const SurfaceCache& unchecked) {
  EXPECT_GE(finer_points(checked), finer_points(unchecked));
  EXPECT_LE(finer_points(checked), finer_points(unchecked) + checked.cell_checks());
}

TEST(SurfaceCache, CornersBeyondTheirObstaclesReachAreRefinedWhereTheyDisagree) {
  // The grazing view of the ground, its value changing along the view by 0.3 % a metre:
  // with the obstacles 20 m away (a corner stands for points within 2 m) rather than
  // 5 km, the cells that span much depth and whose corners differ by more than
  // kCloseSpread are refined further; with the value uniform, or the same ground seen
  // from straight above (cells of little depth), none are.
  const PrimaryHits hits = hits_of_tiled_plane(1e5, 1, kGrazing);
  const SurfaceCache far_away(hits, sloped(3, 5000));
  const SurfaceCache near(hits, sloped(3, 20));
  EXPECT_GT(finer_points(near), finer_points(far_away) + near.cell_checks() + 50);
  const PrimaryHits from_above = hits_of_tiled_plane(1e5, 1, Camera{{0, 0, 100}, {0, 0, 0}, {0, 1, 0}, 20.0});
  const SurfaceCache near_from_above(from_above, sloped(3, 20)), far_from_above(from_above, sloped(3, 5000));
  expect_refined_alike(near_from_above, far_from_above);
  const SurfaceCache uniform_near(hits, sloped(0, 20)), uniform_far(hits, sloped(0, 5000));
  expect_refined_alike(uniform_near, uniform_far);
  EXPECT_EQ(uniform_far.cell_checks(), 0);  // obstacles 5 km away: no cell checked
}

TEST(SurfaceCache, DeepCellsBeyondTheirObstaclesReachMustAgreeWithinOnePercent) {
  // The same grazing view with the value changing a sixth as fast (0.05 % a metre): many
  // deep cells' corners now differ by 1–3 %. Near obstacles such cells are refined all
  // the same: corners that agree within a few percent can hide a dip of the sky light
  // between them (Fig. 7 at 480 × 270: the grass between the tower and the street, 5 %
  // darker than two corners 50 m apart in depth that agreed within 2.1 %). With the
  // 3 % of before, near and far got the same points (1,463); with the 1 %, 1,732 and
  // 1,512 (1,598 and 1,400 since a point at a coarser point's pixel takes its value).
  const PrimaryHits hits = hits_of_tiled_plane(1e5, 1, kGrazing);
  const SurfaceCache far_away(hits, sloped(0.5, 5000)), near(hits, sloped(0.5, 20));
  EXPECT_GT(near.fine_points() + near.pixel_points(), far_away.fine_points() + far_away.pixel_points() + 150);
  std::printf("near %d %d %d %d far %d %d %d %d\n", near.coarse_points(), near.fine_points(), near.pixel_points(),
              near.cell_checks(), far_away.coarse_points(), far_away.fine_points(), far_away.pixel_points(),
              far_away.cell_checks());
}

TEST(SurfaceCache, SkyLightOutshoneByThePixelsOtherLightNeedsNoFinerLevel) {
  // The sky light steps by a factor of 3 across the line x = 0 (an obstacle's edge of
  // visibility, as along a kerb or a ditch): alone, the cells across it are refined down
  // to the pixels; where the pixel's other light (lamps, the glow in front) outshines it
  // a hundredfold, the coarse grid covers all, and the interpolated values stay between
  // the corners'. The least other light among a cell's corners counts: one dark corner
  // is enough to refine.
  const PrimaryHits hits = hits_of_tiled_plane(1e5, 1);
  const double sky_lx = illuminance(Irradiance(0.003f));
  const auto stepped = [](auto other_lx) {
    return [other_lx](const SurfacePoint& p, int x, int) {
      CachedSkyLight v = value_at(p);
      v.diffuse_irradiance = Irradiance(p.position.x < 0 ? 0.001f : 0.003f);
      v.other_lx = other_lx(x);
      return v;
    };
  };
  const SurfaceCache alone(hits, stepped([](int) { return 0.0; }));
  EXPECT_GT(alone.fine_points() + alone.pixel_points(), 50);
  const SurfaceCache outshone(hits, stepped([&](int) { return 100 * sky_lx; }));
  EXPECT_EQ(outshone.fine_points() + outshone.pixel_points(), outshone.cell_checks());
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::optional<CachedSkyLight> v = outshone.interpolate(x + 0.5, y + 0.5, *hits.surface(x, y));
      ASSERT_TRUE(v);
      EXPECT_GE(v->diffuse_irradiance[0], 0.001f * 0.999f);
      EXPECT_LE(v->diffuse_irradiance[0], 0.003f * 1.001f);
    }
  // As bright as the sky light only: the step (a spread of 2/3 of the highest) still
  // exceeds kCornerSpread of sky and other light together.
  const SurfaceCache matched(hits, stepped([&](int) { return sky_lx; }));
  EXPECT_EQ(matched.fine_points() + matched.pixel_points(), alone.fine_points() + alone.pixel_points());
  // Other light from pixel 16 on: the cells across the step (its corners at pixels 16
  // and 32) are covered by the coarse grid (so the cache hands each point its pixel, not
  // its grid index); from pixel 17 on, their corners at 16 are dark, and the least other
  // light among a cell's corners counts: refined as without it.
  const SurfaceCache from_16(hits, stepped([&](int x) { return x >= 16 ? 100 * sky_lx : 0.0; }));
  EXPECT_EQ(from_16.fine_points() + from_16.pixel_points(), from_16.cell_checks());
  const SurfaceCache from_17(hits, stepped([&](int x) { return x >= 17 ? 100 * sky_lx : 0.0; }));
  EXPECT_GT(from_17.fine_points() + from_17.pixel_points(), from_17.cell_checks());
}

// A plane seen from above through a narrow view (0.18 m a pixel), of material 0 but
// where `other(x, y)` holds for the pixel: material 1.
template <typename Other>
PrimaryHits hits_of_narrow_view(const Other& other) {
  const ImageCamera camera(Camera{{0, 0, 100}, {0, 0, 0}, {0, 1, 0}, 5.0}, kWidth, kHeight);
  return PrimaryHits(camera, kWidth, kHeight, [&](const Ray& ray) {
    const double t = -ray.origin.z / ray.direction.z;
    const Vec3 p = ray.origin + t * ray.direction;
    const auto pixel = camera.project(p);
    const int x = static_cast<int>(std::floor(pixel->first)), y = static_cast<int>(std::floor(pixel->second));
    return PrimaryHit{0, SurfacePoint{p, {0, 0, 1}, t, other(x, y) ? 1u : 0u}};
  });
}

TEST(SurfaceCache, ASliverTakesANeighboursValueOnlyWithinItsObstaclesReach) {
  // A plane seen from above through a narrow view (0.18 m a pixel, so that a grid
  // point 5 pixels away is within the cache's reach on screen) is of one material but
  // for two pixels of another: (8, 8), a fine grid point, and (13, 9), whose fine cell
  // has no corner on it. The second takes the first's value as a sliver of its surface
  // when the first's obstacles are far (5 km: it stands for points within 500 m); when
  // they are 1 m away (within 0.1 m) it gets a point of its own.
  const PrimaryHits hits = hits_of_narrow_view([](int x, int y) { return (x == 8 && y == 8) || (x == 13 && y == 9); });
  ASSERT_EQ(hits.surface(8, 8)->material, 1u);
  ASSERT_EQ(hits.surface(13, 9)->material, 1u);
  auto with_obstacles_at = [](double obstacle_m) {
    return [obstacle_m](const SurfacePoint& p, int, int) {
      CachedSkyLight v = value_at(p);
      v.obstacle_distance_m = obstacle_m;
      return v;
    };
  };
  const SurfacePoint& sliver = *hits.surface(13, 9);
  const float grid_points_value = value_at(*hits.surface(8, 8)).diffuse_irradiance[0];
  const float own_value = value_at(sliver).diffuse_irradiance[0];
  ASSERT_GT(std::abs(own_value - grid_points_value), 0.5f);  // 0.9 m apart in x
  const SurfaceCache far(hits, with_obstacles_at(5000));
  const SurfaceCache near(hits, with_obstacles_at(1));
  EXPECT_FLOAT_EQ(far.interpolate(13.5, 9.5, sliver)->diffuse_irradiance[0], grid_points_value);
  EXPECT_FLOAT_EQ(near.interpolate(13.5, 9.5, sliver)->diffuse_irradiance[0], own_value);
  EXPECT_EQ(near.pixel_points(), far.pixel_points() + 1);
}

TEST(SurfaceCache, ALoneCornerStandsInForNoPointOnTheGrids) {
  // The narrow view from above (0.18 m a pixel) of a plane of one material but for two
  // squares of another: pixels 14–21 (one coarse grid point on it, (16, 16), and four
  // fine ones) and pixels 40–41 (one fine grid point, (40, 40), and no coarse one). The
  // value changes along the plane and the obstacles are far (value_at: no obstacle
  // distance), so within its obstacles' reach a lone corner would have stood in for its
  // whole cell (until 2026-12-06). Now the first square's point at pixel (19, 19) is
  // interpolated from its four fine corners (value_at is linear: exact), and the second
  // square's point at (41, 41) gets its own centre.
  const PrimaryHits hits = hits_of_narrow_view([](int x, int y) {
    return (x >= 14 && x <= 21 && y >= 14 && y <= 21) || (x >= 40 && x <= 41 && y >= 40 && y <= 41);
  });
  const SurfaceCache cache(hits, value_at);
  const SurfacePoint& in_first = *hits.surface(19, 19);
  const float lone_coarse = value_at(*hits.surface(16, 16)).diffuse_irradiance[0];
  const float own_first = value_at(in_first).diffuse_irradiance[0];
  ASSERT_GT(std::abs(own_first - lone_coarse), 0.3f);  // 3 pixels apart in x and y
  EXPECT_NEAR(cache.interpolate(19.5, 19.5, in_first)->diffuse_irradiance[0], own_first, 0.01f);
  const SurfacePoint& in_second = *hits.surface(41, 41);
  const float lone_fine = value_at(*hits.surface(40, 40)).diffuse_irradiance[0];
  const float own_second = value_at(in_second).diffuse_irradiance[0];
  ASSERT_GT(std::abs(own_second - lone_fine), 0.1f);
  EXPECT_FLOAT_EQ(cache.interpolate(41.5, 41.5, in_second)->diffuse_irradiance[0], own_second);
}

}  // namespace
}  // namespace skylit
