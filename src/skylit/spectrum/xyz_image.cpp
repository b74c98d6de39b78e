#include "skylit/spectrum/xyz_image.h"

#include <stdexcept>
#include <string>

namespace skylit {

XyzImage::XyzImage(int w, int h) : width(w), height(h) {
  if (w < 0 || h < 0) throw std::invalid_argument("XyzImage: negative size");
  xyz.assign(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
}

namespace {
std::size_t checked_index(const XyzImage& image, int x, int y) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height)
    throw std::out_of_range("XyzImage: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") outside " +
                            std::to_string(image.width) + "x" + std::to_string(image.height));
  return 3 * (static_cast<std::size_t>(y) * image.width + x);
}
}  // namespace

Xyz XyzImage::at(int x, int y) const {
  const std::size_t i = checked_index(*this, x, y);
  return {xyz[i], xyz[i + 1], xyz[i + 2]};
}

void XyzImage::set(int x, int y, const Xyz& v) {
  const std::size_t i = checked_index(*this, x, y);
  xyz[i] = static_cast<float>(v.x);
  xyz[i + 1] = static_cast<float>(v.y);
  xyz[i + 2] = static_cast<float>(v.z);
}

}  // namespace skylit
