#include "skylit/render/primary_hits.h"

#include <tbb/parallel_for.h>

namespace skylit {

PrimaryHits::PrimaryHits(const ImageCamera& camera, int width, int height, const Trace& trace)
    : width_(width), height_(height), hits_(static_cast<size_t>(width) * height) {
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x)
      hits_[static_cast<size_t>(y) * width + x] = trace(camera.ray_through(x + 0.5, y + 0.5));
  });
}

}  // namespace skylit
