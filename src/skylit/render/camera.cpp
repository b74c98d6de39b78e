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

std::optional<std::pair<double, double>> PinholeCamera::project(const Vec3& point) const {
  const Vec3 v = point - position_;
  const double depth = dot(v, forward_);
  if (!(depth > 0)) return std::nullopt;
  const double u = dot(v, right_) / depth / half_width_, w = dot(v, up_) / depth / half_height_;
  return std::pair{(u + 1.0) * width_ / 2.0, (1.0 - w) * height_ / 2.0};
}

double PinholeCamera::pixel_solid_angle(double x, double y) const {
  // A patch dA of the image plane at distance 1, seen at angle α off the axis, covers
  // dA·cos³α (its distance is 1/cos α and it is tilted by α).
  const double u = (2.0 * x / width_ - 1.0) * half_width_;
  const double v = (1.0 - 2.0 * y / height_) * half_height_;
  const double cos_alpha = 1.0 / std::sqrt(1.0 + u * u + v * v);
  const double area = (2.0 * half_width_ / width_) * (2.0 * half_height_ / height_);
  return area * cos_alpha * cos_alpha * cos_alpha;
}

}  // namespace skylit
