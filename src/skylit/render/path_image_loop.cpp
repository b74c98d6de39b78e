#include "skylit/render/path_image_loop.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "skylit/render/film.h"
#include "skylit/render/seen_lamps.h"
#include "skylit/spectrum/cie.h"

namespace skylit {

namespace {

// D65's white point in XYZ with Y = 1: a grey of the standard error's luminance.
constexpr double kWhiteX = 0.95047, kWhiteZ = 1.08883;

}  // namespace

PathImage render_path_image(const PreparedScene& scene, const PathIntegrator& integrator,
                            const RenderOptions& options) {
  const RenderSettings& settings = scene.scene().render;
  const int width = settings.width, height = settings.height, samples = settings.samples_per_pixel;
  const ImageCamera camera(scene.scene().camera, width, height);
  Film film(width, height);
  XyzImage standard_error(width, height);
  // The image loop's tiles (image_loop.h), so that a split render shares them alike.
  const int tile_count = image_tile_count(width, height);
  int own_tiles = 0;
  for (int tile = 0; tile < tile_count; ++tile) own_tiles += options.share.renders(tile) ? 1 : 0;
  std::mutex progress_mutex;
  int done = 0;
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
      for (int tile = range.begin(); tile != range.end(); ++tile) {
        if (!options.share.renders(tile)) continue;
        const ImageTile t = image_tile(tile, width, height);
        for (int y = t.y0; y < t.y1; ++y)
          for (int x = t.x0; x < t.x1; ++x) {
            if (!camera.sees(x + 0.5, y + 0.5)) continue;  // outside a fisheye's circle: black
            Spectrum sum(0.0f);
            double y_sum = 0, y_squares = 0;
            for (int s = 0; s < samples; ++s) {
              CounterRandom random(settings.seed, static_cast<uint64_t>(y) * width + x, static_cast<uint64_t>(s));
              const double px = x + random.uniform(), py = y + random.uniform();
              const Spectrum radiance = integrator.sample(camera.ray_through(px, py), random).spectrum();
              sum += radiance;
              const double luminance_cd = luminance(radiance);
              y_sum += luminance_cd;
              y_squares += luminance_cd * luminance_cd;
            }
            film.set(x, y, sum * static_cast<float>(1.0 / samples));
            const double mean = y_sum / samples;
            const double variance =
                samples > 1 ? std::max(0.0, (y_squares - samples * mean * mean) / (samples - 1)) : 0.0;
            const double error = std::sqrt(variance / samples);
            standard_error.set(x, y, {kWhiteX * error, error, kWhiteZ * error});
          }
        if (options.on_progress) {
          std::lock_guard lock(progress_mutex);
          options.on_progress(++done, own_tiles);
        }
      }
    });
  });
  if (options.share.parts > 1) {
    options.share.exchange(film.pixels());
    options.share.exchange(standard_error);
  }
  add_seen_lamps(scene, camera, film);
  return {film.take(), std::move(standard_error)};
}

}  // namespace skylit
