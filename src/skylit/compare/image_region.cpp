// whole_image_region and rectangle_region (image_region.h).
#include "skylit/compare/image_region.h"

namespace skylit {

ImageRegion rectangle_region(std::string name, int width, int x0, int y0, int x1, int y1) {
  ImageRegion region{std::move(name), {}};
  if (x1 > x0 && y1 > y0) region.pixels.reserve(static_cast<std::size_t>(x1 - x0) * (y1 - y0));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) region.pixels.push_back(static_cast<uint32_t>(y) * width + x);
  return region;
}

ImageRegion whole_image_region(int width, int height) { return rectangle_region("all", width, 0, 0, width, height); }

}  // namespace skylit
