// An image of absolute CIE XYZ, what the renderer makes and the image writers
// (io/image/image.h) write.
#pragma once

#include "skylit/core/huge_pages.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {

// An image of absolute CIE XYZ: Y is luminance in cd/m². Rows top to bottom.
struct XyzImage {
  int width = 0, height = 0;
  HugePageVector<float> xyz;  // 3 per pixel, row-major from the top-left pixel (11 MB at 1280 × 720)

  XyzImage() = default;
  XyzImage(int width, int height);  // all black; std::invalid_argument if negative

  // Checked (std::out_of_range): a renderer's off-by-one must not scribble memory.
  Xyz at(int x, int y) const;
  void set(int x, int y, const Xyz& value);
};

}  // namespace skylit
