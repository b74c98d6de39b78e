// An image of absolute CIE XYZ, what the renderer makes and the image writers
// (io/image/image.h) write.
#pragma once

#include <vector>

#include "skylit/spectrum/color_space.h"

namespace skylit {

// An image of absolute CIE XYZ: Y is luminance in cd/m². Rows top to bottom.
struct XyzImage {
  int width = 0, height = 0;
  std::vector<float> xyz;  // 3 per pixel, row-major from the top-left pixel

  XyzImage() = default;
  XyzImage(int width, int height);  // all black; std::invalid_argument if negative

  // Checked (std::out_of_range): a renderer's off-by-one must not scribble memory.
  Xyz at(int x, int y) const;
  void set(int x, int y, const Xyz& value);
};

}  // namespace skylit
