// A named set of pixels of an image, over which two renders are compared (skylit
// compare): from a rectangle, a mask colour, or the whole image.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace skylit {

struct ImageRegion {
  std::string name;
  std::vector<uint32_t> pixels;  // indices y · width + x, ascending
};

// The whole `width` × `height` image, named "all".
ImageRegion whole_image_region(int width, int height);

// The pixels x0 ≤ x < x1, y0 ≤ y < y1 of a `width`-wide image (the caller checks that
// the rectangle lies inside it).
ImageRegion rectangle_region(std::string name, int width, int x0, int y0, int x1, int y1);

}  // namespace skylit
