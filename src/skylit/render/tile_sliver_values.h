// Sky light computed for samples that the image's sky-light cache has no value for
// (slivers of a surface that no pixel centre near them sees: the sides of window
// reveals and frames a quarter of a pixel wide), kept while one tile of the image is
// rendered, so that a later sample of the tile within 2 pixels on the same surface takes
// the value instead of computing its own, as the cache's per-pixel level lets the
// samples near a pixel centre share the centre's (docs/sky-light.md gives what this
// changes in the image). The tile's samples come in a fixed scan order, so the image does
// not depend on the number of threads.
#pragma once

#include <vector>

#include "skylit/render/surface_cache.h"

namespace skylit {

class TileSliverValues {
 public:
  // How far (pixels, on the screen) a sample may take another's value.
  static constexpr double kReachPixels = 2.0;

  // The value of the nearest sample added at most kReachPixels away whose point lies on
  // the same surface and within reach (surface_cache.h, cache_corner_agreement.h); null
  // if none.
  const CachedSkyLight* find(double x, double y, const SurfacePoint& point) const;
  // A value computed for the sample at image position (x, y) in pixels; samples are
  // added row of pixels by row of pixels, top down.
  void add(double x, double y, const SurfacePoint& point, const CachedSkyLight& value);

 private:
  struct Entry {
    double x, y;
    SurfacePoint point;
    CachedSkyLight value;
  };
  std::vector<Entry> entries_;
};

}  // namespace skylit
