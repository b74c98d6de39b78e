#include "skylit/render/image_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "skylit/core/angles.h"
#include "skylit/render/film.h"
#include "skylit/render/seen_lamps.h"
#include "skylit/spectrum/cie.h"

namespace skylit {

namespace {

// The sky light the image cache keeps for the surface point seen through pixel (x, y),
// with what else the pixel shows (CachedSkyLight::other_lx), which the cache judges its
// corners against: the lamps' glow in the fog in front of the surface, counted as π
// times its luminance, the sky illuminance that would show as bright on a white surface
// seen without loss (a darker surface, or fog that dims it, only makes the glow count
// more, so this is the least it counts, for any material's diffuse part). The glow
// changes smoothly across the image but at the edges of objects and beams, which the
// cache's corners see too; the lamps' light on surfaces does not count, as a pole's
// shadow may cross a cell whose corners are all lit.
//
// Where the glow outshines the most sky light the point could have kFaintSky times
// (BandsIntegrator::sky_light_bound_lx), the sky light is under 2 % of the pixel, and its
// diffuse part is found by the cheaper integral (BandsIntegrator::faint_sky_light_at),
// off by a few per cent of it, up to about 20 % where obstacles seeing other skies hide
// much of it: under 0.4 % of the pixel.
constexpr double kFaintSky = 50;

CachedSkyLight cached_sky_light(const BandsIntegrator& integrator, const LampGlowImage* glow, const Vec3& eye, int x,
                                int y, const SurfacePoint& point, bool one_pixel) {
  const double glow_lx = glow ? kPi * luminance(glow->centre_glow(x, y)) : 0;
  CachedSkyLight value = glow && glow_lx >= kFaintSky * integrator.sky_light_bound_lx(point)
                             ? integrator.faint_sky_light_at(point, eye)
                         : one_pixel ? integrator.sky_light_for_one_pixel(point, eye)
                                     : integrator.sky_light_at(point, eye);
  value.other_lx = glow_lx;
  return value;
}

// Neighbouring pixel centres that differ by more than this fraction (in X, Y or Z) mark
// an edge, where the pixel gets its full grid of samples.
constexpr double kEdgeContrast = 0.05;

// Whether pixel (x, y) lies on an edge: its centre and one of its four neighbours' met
// different objects, or differ in any of X, Y, Z by more than kEdgeContrast.
bool is_edge(const XyzImage& image, const PrimaryHits& hits, int x, int y) {
  const Xyz a = image.at(x, y);
  const uint32_t mesh = hits.at(x, y).mesh;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if ((dx == 0) == (dy == 0) || nx < 0 || ny < 0 || nx >= image.width || ny >= image.height) continue;
      if (hits.at(nx, ny).mesh != mesh) return true;
      const Xyz b = image.at(nx, ny);
      for (auto [p, q] : {std::pair{a.x, b.x}, std::pair{a.y, b.y}, std::pair{a.z, b.z}})
        if (std::abs(p - q) > kEdgeContrast * std::max(std::abs(p), std::abs(q))) return true;
    }
  return false;
}

}  // namespace

int image_tile_count(int width, int height) {
  return ((width + kImageTileSize - 1) / kImageTileSize) * ((height + kImageTileSize - 1) / kImageTileSize);
}

ImageTile image_tile(int tile, int width, int height) {
  const int tiles_x = (width + kImageTileSize - 1) / kImageTileSize;
  const int x0 = (tile % tiles_x) * kImageTileSize, y0 = (tile / tiles_x) * kImageTileSize;
  return {x0, y0, std::min(x0 + kImageTileSize, width), std::min(y0 + kImageTileSize, height)};
}

namespace {

// Seconds since the last call (or since it was made).
class Stopwatch {
 public:
  double lap_s() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

XyzImage render_image(const PreparedScene& scene, const BandsIntegrator& integrator, const RenderOptions& options) {
  const RenderSettings& settings = scene.scene().render;
  const int width = settings.width, height = settings.height, n = settings.samples_per_axis;
  const ImageCamera camera(scene.scene().camera, width, height);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

  // What every pixel's centre sees, then the caches made from it: the sky light at a
  // sparse grid of those points, and the lamps' glow in fog.
  std::unique_ptr<PrimaryHits> hits;
  std::unique_ptr<SurfaceCache> sky_light;
  std::unique_ptr<LampGlowImage> glow;
  FrameBreakdown unused;
  FrameBreakdown& breakdown = options.breakdown ? *options.breakdown : unused;
  breakdown = {};
  Stopwatch stopwatch;
  arena.execute([&] {
    hits =
        std::make_unique<PrimaryHits>(camera, width, height, [&](const Ray& ray) { return integrator.first_hit(ray); });
    breakdown.primary_hits_s = stopwatch.lap_s();
    const Vec3& eye = scene.scene().camera.position;
    // The glow first: the sky-light cache judges its corners against it.
    if (scene.lamps() && scene.fog()) glow = std::make_unique<LampGlowImage>(camera, *hits, *scene.lamps());
    auto cached = [&](bool one_pixel) {
      return [&, one_pixel](const SurfacePoint& p, int x, int y) {
        return cached_sky_light(integrator, glow.get(), eye, x, y, p, one_pixel);
      };
    };
    if (!options.exact_sky_light) sky_light = std::make_unique<SurfaceCache>(*hits, cached(false), cached(true));
  });
  breakdown.caches_s = stopwatch.lap_s();
  if (sky_light) {
    breakdown.coarse_points = sky_light->coarse_points();
    breakdown.fine_points = sky_light->fine_points();
    breakdown.cell_checks = sky_light->cell_checks();
    breakdown.pixel_points = sky_light->pixel_points();
    breakdown.pixels_between = sky_light->pixels_between();
  }
  const ImageCaches caches{sky_light.get(), glow.get()};

  // A pixel's value from a regular grid × grid of samples inside it, averaged with equal
  // weights. Grid 1 is the pixel's centre, whose hit is known already.
  auto pixel_value = [&](int x, int y, int grid, TileSliverValues& slivers) {
    if (!camera.sees(x + 0.5, y + 0.5)) return Spectrum(0.0f);  // outside a fisheye's circle: black
    PixelViewPath pixel_path;
    if (grid == 1) {
      const SampleContext context{x + 0.5, y + 0.5, caches, &pixel_path, &slivers};
      return integrator.radiance(camera.ray_through(x + 0.5, y + 0.5), hits->at(x, y), context).spectrum();
    }
    Spectrum sum;
    for (int sy = 0; sy < grid; ++sy)
      for (int sx = 0; sx < grid; ++sx) {
        const double px = x + (sx + 0.5) / grid, py = y + (sy + 0.5) / grid;
        const Ray ray = camera.ray_through(px, py);
        const SampleContext context{px, py, caches, &pixel_path, &slivers};
        sum += integrator.radiance(ray, integrator.first_hit(ray), context).spectrum();
      }
    return sum * static_cast<float>(1.0 / (grid * grid));
  };

  // Two passes over the tiles (adaptive antialiasing): first one sample at every
  // pixel's centre; then the full n × n grid only where an edge runs (is_edge).
  // Elsewhere the image is smooth at the pixel's scale and its centre stands for the
  // grid's mean.
  const int tile_count = image_tile_count(width, height);
  const int passes = n > 1 ? 2 : 1;
  int own_tiles = 0;
  for (int tile = 0; tile < tile_count; ++tile) own_tiles += options.share.renders(tile) ? 1 : 0;
  std::mutex progress_mutex;
  int tiles_done = 0;
  Film centres(width, height);
  std::optional<Film> refined;  // the second pass reads the first's film and writes here
  auto render_tile = [&](int tile, int pass) {
    if (!options.share.renders(tile)) return;
    const ImageTile t = image_tile(tile, width, height);
    TileSliverValues slivers;  // the samples' own sky light, shared within the tile
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) {
        if (pass == 0)
          centres.set(x, y, pixel_value(x, y, passes == 1 ? n : 1, slivers));
        else if (is_edge(centres.image(), *hits, x, y))
          refined->set(x, y, pixel_value(x, y, n, slivers));
      }
    if (options.on_progress) {
      std::lock_guard lock(progress_mutex);
      options.on_progress(++tiles_done, passes * own_tiles);
    }
  };
  for (int pass = 0; pass < passes; ++pass) {
    if (pass == 1) refined = centres;
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
        for (int tile = range.begin(); tile != range.end(); ++tile) render_tile(tile, pass);
      });
    });
    (pass == 0 ? breakdown.centres_pass_s : breakdown.edges_pass_s) = stopwatch.lap_s();
    // The edges of the second pass look at neighbours across tiles: every process
    // needs the whole first pass.
    if (options.share.parts > 1) options.share.exchange((pass == 0 ? centres : *refined).pixels());
    stopwatch.lap_s();  // the exchange's time is the processes', not this pass's
  }
  breakdown.obstacle_patches = integrator.obstacle_patch_counts();
  Film& film = refined ? *refined : centres;
  add_seen_lamps(scene, camera, film);
  return film.take();
}

}  // namespace skylit
