// The image loop: primary visibility once per frame (primary_hits.h), the caches built
// from it (the sky light on surfaces, the lamps' glow), then the pixels in tiles in
// parallel, in two passes (adaptive antialiasing), into the film. Every sample's light
// comes from the one per-ray function, BandsIntegrator::radiance. Pixels are computed
// on a fixed grid of samples, and the samples of one tile (which share the sky light
// that the cache has no value for, tile_sliver_values.h) in a fixed order, so the
// output does not depend on the number of threads.
#pragma once

#include <functional>

#include "skylit/render/bands_integrator.h"
#include "skylit/render/frame_breakdown.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// The image is rendered in square tiles of this many pixels, numbered row by row; the
// last column and row may be narrower.
inline constexpr int kImageTileSize = 32;
struct ImageTile {
  int x0, y0, x1, y1;  // pixels x0 ≤ x < x1, y0 ≤ y < y1
};
int image_tile_count(int width, int height);
ImageTile image_tile(int tile, int width, int height);

// One image split over processes (MPI; apps/skylit/process_group.h): this process renders
// the tiles whose number % parts == part. After each pass over the tiles `exchange`
// gets the image with this process's tiles done and must fill in every other tile from
// the process that rendered it, so that each process continues with the whole image.
struct ImageShare {
  int part = 0, parts = 1;
  std::function<void(XyzImage& image)> exchange;

  bool renders(int tile) const { return tile % parts == part; }
};

struct RenderOptions {
  int threads = 0;  // 0: as many as the machine has
  // Called now and then with the number of tiles done and the total; from any thread,
  // never concurrently.
  std::function<void(int done, int total)> on_progress;
  ImageShare share{};  // the whole image by default
  // No sky-light cache: every sample computes its sky light exactly (the reference the
  // cache's accuracy is measured against; many times slower).
  bool exact_sky_light = false;
  FrameBreakdown* breakdown = nullptr;  // filled in when given
};

XyzImage render_image(const PreparedScene& scene, const BandsIntegrator& integrator, const RenderOptions& options);

}  // namespace skylit
