// A pinhole camera: maps image positions to rays in the world frame.
#pragma once

#include <optional>
#include <utility>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/scene/scene.h"

namespace skylit {

class PinholeCamera {
 public:
  PinholeCamera(const Camera& camera, int width, int height);
  // The ray through the image position (x, y) in pixels, (0, 0) the top-left corner
  // of the top-left pixel; the direction is unit length.
  Ray ray_through(double x, double y) const;
  // Where a world point appears in the image (pixels, as above), if it lies in front of
  // the camera; it may fall outside the image.
  std::optional<std::pair<double, double>> project(const Vec3& point) const;
  // The solid angle (sr) one pixel covers around image position (x, y).
  double pixel_solid_angle(double x, double y) const;

 private:
  Vec3 position_, forward_, right_, up_;
  double half_width_, half_height_;  // of the image plane at distance 1
  int width_, height_;
};

}  // namespace skylit
