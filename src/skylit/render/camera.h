// The camera: maps image positions to rays in the world frame and back, for every
// projection of scene/Camera. With a = 2x/W − 1 (right) and b = 1 − 2y/H (up) the
// image position in [−1, 1]², and forward, right, up the camera's frame:
//   perspective   d = forward + (a + 2 shift_x)·tan(v/2)·(W/H)·right + (b + 2 shift_y)·tan(v/2)·up
//   fisheyes      p = a·W/H, q = b, r = √(p² + q²) (1 at the top edge); θ from r:
//                   equidistant θ = r·v/2;  equisolid sin(θ/2) = r·sin(v/4);
//                   hemispherical sin θ = r·sin(v/2)
//                 d = cos θ·forward + sin θ·(p·right + q·up)/r, for r ≤ 1 (the image
//                 circle, touching the top and bottom edges; black outside)
//   cylindrical   φ = a·h/2, d = cos φ·forward + sin φ·right + b·tan(v/2)·up
//   equirectangular φ = a·h/2, e = b·v/2, d = cos e·(cos φ·forward + sin φ·right) + sin e·up
// with v = vertical_fov_deg and h = horizontal_fov_deg in radians.
#pragma once

#include <optional>
#include <utility>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/scene/scene.h"

namespace skylit {

class ImageCamera {
 public:
  ImageCamera(const Camera& camera, int width, int height);
  // Whether the image position (x, y) in pixels ((0, 0) the top-left corner of the
  // top-left pixel) shows a direction: false outside a fisheye's image circle.
  bool sees(double x, double y) const;
  // The ray through the image position (x, y); the direction is unit length. Where
  // sees(x, y) is false it is the nearest direction that is seen.
  Ray ray_through(double x, double y) const;
  // Where a world point appears in the image (pixels, as above), if its direction is
  // one the projection shows; it may fall outside the image.
  std::optional<std::pair<double, double>> project(const Vec3& point) const;
  // The solid angle (sr) one pixel covers around image position (x, y).
  double pixel_solid_angle(double x, double y) const;
  Projection projection() const { return projection_; }

 private:
  // Image position in [−1, 1]² (a right, b up) and back.
  std::pair<double, double> normalised(double x, double y) const;
  // θ for a fisheye's radius r, if r ≤ 1 (inside its image circle).
  std::optional<double> fisheye_angle(double r) const;
  double fisheye_radius(double theta) const;

  Projection projection_;
  Vec3 position_, forward_, right_, up_;
  double vertical_fov_, horizontal_fov_;  // radians
  double half_width_, half_height_;       // perspective: of the image plane at distance 1
  double shift_x_, shift_y_;
  double aspect_;  // width / height
  int width_, height_;
};

}  // namespace skylit
