#include "skylit/render/camera.h"

#include <cmath>

namespace skylit {

PinholeCamera::PinholeCamera(const Camera& camera, int width, int height)
    : position_(camera.position), width_(width), height_(height) {
  forward_ = normalize(camera.look_at - camera.position);
  right_ = normalize(cross(forward_, camera.up));
  up_ = cross(right_, forward_);
  half_height_ = std::tan(radians(camera.vertical_fov_deg) / 2.0);
  half_width_ = half_height_ * width / height;
}

Ray PinholeCamera::ray_through(double x, double y) const {
  const double u = (2.0 * x / width_ - 1.0) * half_width_;
  const double v = (1.0 - 2.0 * y / height_) * half_height_;
  return Ray{position_, normalize(forward_ + u * right_ + v * up_)};
}

}  // namespace skylit
