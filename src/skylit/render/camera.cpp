// The projections of camera.h, forward (ray_through), backward (project) and their
// Jacobians (pixel_solid_angle).
#include "skylit/render/camera.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

ImageCamera::ImageCamera(const Camera& camera, int width, int height)
    : projection_(camera.projection),
      position_(camera.position),
      vertical_fov_(radians(camera.vertical_fov_deg)),
      horizontal_fov_(radians(camera.horizontal_fov_deg)),
      shift_x_(camera.shift_x),
      shift_y_(camera.shift_y),
      aspect_(double(width) / height),
      width_(width),
      height_(height) {
  forward_ = normalize(camera.look_at - camera.position);
  right_ = normalize(cross(forward_, camera.up));
  up_ = cross(right_, forward_);
  half_height_ = std::tan(vertical_fov_ / 2.0);
  half_width_ = half_height_ * aspect_;
}

std::pair<double, double> ImageCamera::normalised(double x, double y) const {
  return {2.0 * x / width_ - 1.0, 1.0 - 2.0 * y / height_};
}

std::optional<double> ImageCamera::fisheye_angle(double r) const {
  if (r > 1 + 1e-12) return std::nullopt;  // outside the image circle
  double theta = 0;
  switch (projection_) {
    case Projection::fisheye_equisolid: {
      theta = 2 * std::asin(std::min(1.0, r * std::sin(vertical_fov_ / 4)));
      break;
    }
    case Projection::fisheye_hemispherical: {
      theta = std::asin(std::min(1.0, r * std::sin(std::min(vertical_fov_, kPi) / 2)));
      break;
    }
    default:  // equidistant
      theta = r * vertical_fov_ / 2;
  }
  return theta;
}

double ImageCamera::fisheye_radius(double theta) const {
  switch (projection_) {
    case Projection::fisheye_equisolid:
      return std::sin(theta / 2) / std::sin(vertical_fov_ / 4);
    case Projection::fisheye_hemispherical:
      return std::sin(theta) / std::sin(std::min(vertical_fov_, kPi) / 2);
    default:
      return theta / (vertical_fov_ / 2);
  }
}

bool ImageCamera::sees(double x, double y) const {
  const auto [a, b] = normalised(x, y);
  switch (projection_) {
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
    case Projection::fisheye_hemispherical:
      return fisheye_angle(std::hypot(a * aspect_, b)).has_value();
    default:
      return true;
  }
}

Ray ImageCamera::ray_through(double x, double y) const {
  const auto [a, b] = normalised(x, y);
  Vec3 d;
  switch (projection_) {
    case Projection::perspective:
      d = forward_ + ((a + 2 * shift_x_) * half_width_) * right_ + ((b + 2 * shift_y_) * half_height_) * up_;
      break;
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
    case Projection::fisheye_hemispherical: {
      const double p = a * aspect_, q = b, r = std::hypot(p, q);
      if (r == 0) {
        d = forward_;
        break;
      }
      // Outside the image circle: the circle's edge in the same direction.
      const double theta = fisheye_angle(std::min(r, 1.0)).value_or(0);
      d = std::cos(theta) * forward_ + (std::sin(theta) / r) * (p * right_ + q * up_);
      break;
    }
    case Projection::cylindrical: {
      const double phi = a * horizontal_fov_ / 2;
      d = std::cos(phi) * forward_ + std::sin(phi) * right_ + (b * half_height_) * up_;
      break;
    }
    case Projection::equirectangular: {
      const double phi = a * horizontal_fov_ / 2, e = b * vertical_fov_ / 2;
      d = std::cos(e) * (std::cos(phi) * forward_ + std::sin(phi) * right_) + std::sin(e) * up_;
      break;
    }
  }
  return Ray{position_, normalize(d)};
}

std::optional<std::pair<double, double>> ImageCamera::project(const Vec3& point) const {
  const Vec3 v = point - position_;
  const double f = dot(v, forward_), s = dot(v, right_), u = dot(v, up_);
  double a = 0, b = 0;
  switch (projection_) {
    case Projection::perspective:
      if (!(f > 0)) return std::nullopt;
      a = s / f / half_width_ - 2 * shift_x_;
      b = u / f / half_height_ - 2 * shift_y_;
      break;
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
    case Projection::fisheye_hemispherical: {
      const double side = std::hypot(s, u);
      const double theta = std::atan2(side, f);
      if (projection_ == Projection::fisheye_hemispherical && theta > kPi / 2) return std::nullopt;
      const double r = fisheye_radius(theta);
      if (!fisheye_angle(r)) return std::nullopt;
      const double p = side > 0 ? r * s / side : 0, q = side > 0 ? r * u / side : 0;
      a = p / aspect_;
      b = q;
      break;
    }
    case Projection::cylindrical: {
      const double across = std::hypot(f, s);
      if (!(across > 0)) return std::nullopt;
      a = std::atan2(s, f) / (horizontal_fov_ / 2);
      b = u / across / half_height_;
      break;
    }
    case Projection::equirectangular: {
      const double across = std::hypot(f, s);
      a = std::atan2(s, f) / (horizontal_fov_ / 2);
      b = std::atan2(u, across) / (vertical_fov_ / 2);
      break;
    }
  }
  return std::pair{(a + 1.0) * width_ / 2.0, (1.0 - b) * height_ / 2.0};
}

double ImageCamera::pixel_solid_angle(double x, double y) const {
  const auto [a, b] = normalised(x, y);
  const double dadb = (2.0 / width_) * (2.0 / height_);  // one pixel in (a, b)
  switch (projection_) {
    case Projection::perspective: {
      // A patch dA of the image plane at distance 1, seen at angle α off the axis,
      // covers dA·cos³α (its distance is 1/cos α and it is tilted by α).
      const double u = (a + 2 * shift_x_) * half_width_, v = (b + 2 * shift_y_) * half_height_;
      const double cos_alpha = 1.0 / std::sqrt(1.0 + u * u + v * v);
      return dadb * half_width_ * half_height_ * cos_alpha * cos_alpha * cos_alpha;
    }
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
    case Projection::fisheye_hemispherical: {
      // In (p, q) = (a·W/H, b) a pixel covers dadb·W/H; dΩ = sin θ dθ dψ and
      // dA = r dr dψ, so dΩ/dA = sin θ / (r · dr/dθ).
      const double r = std::hypot(a * aspect_, b);
      const std::optional<double> theta = fisheye_angle(r);
      if (!theta) return 0;
      const double dpdq = dadb * aspect_;
      if (projection_ == Projection::fisheye_equisolid) {
        const double s = std::sin(vertical_fov_ / 4);
        return dpdq * 4 * s * s;  // equal-area
      }
      if (projection_ == Projection::fisheye_hemispherical) {
        const double s = std::sin(std::min(vertical_fov_, kPi) / 2);
        return dpdq * s * s / std::max(std::cos(*theta), 1e-9);
      }
      const double c = vertical_fov_ / 2;
      return dpdq * c * c * (*theta > 0 ? std::sin(*theta) / *theta : 1.0);
    }
    case Projection::cylindrical: {
      // dΩ = cos e de dφ with tan e = t: de = cos²e dt, so dΩ = cos³e dt dφ.
      const double t = b * half_height_;
      const double cos_e = 1.0 / std::sqrt(1.0 + t * t);
      return dadb * (horizontal_fov_ / 2) * half_height_ * cos_e * cos_e * cos_e;
    }
    case Projection::equirectangular:
      return dadb * (horizontal_fov_ / 2) * (vertical_fov_ / 2) * std::cos(b * vertical_fov_ / 2);
  }
  return 0;
}

}  // namespace skylit
