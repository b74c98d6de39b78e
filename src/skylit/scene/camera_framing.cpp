#include "skylit/scene/camera_framing.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {
namespace {

std::array<Vec3, 8> corners(const BoundingBox& box) {
  std::array<Vec3, 8> out;
  for (int k = 0; k < 8; ++k)
    out[k] = {k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y, k & 4 ? box.hi.z : box.lo.z};
  return out;
}

Vec3 up_for(const Vec3& forward) {
  // Looking (nearly) straight up or down, "up" in the image is north.
  return std::abs(forward.z) > 0.9999 * length(forward) ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
}

// The image plane's axes for a view along `forward`, as the pinhole camera builds them.
struct ViewAxes {
  Vec3 forward, right, up;
  explicit ViewAxes(const Vec3& view) : forward(normalize(view)) {
    right = normalize(cross(forward, up_for(view)));
    up = cross(right, forward);
  }
};

}  // namespace

// A corner p, at x, y across and z along the view from the box's centre c, shows
// within the fraction kFramingFill of the half fields (tangents tx, ty) from a camera
// at c − d·forward when |x| ≤ kFramingFill·tx·(d + z) and likewise for y: so d is the
// largest of |x| / (kFramingFill·tx) − z and |y| / (kFramingFill·ty) − z over the corners.
Camera frame_from_direction(const BoundingBox& box, double from_azimuth_deg, double elevation_deg,
                            double vertical_fov_deg, double aspect) {
  const Vec3 center = box.center();
  const ViewAxes axes(-direction_from_altitude_azimuth(elevation_deg, from_azimuth_deg));
  const double ty = kFramingFill * std::tan(0.5 * radians(vertical_fov_deg)), tx = ty * aspect;
  double distance = 1e-3;
  for (const Vec3& p : corners(box)) {
    const Vec3 q = p - center;
    const double x = dot(q, axes.right), y = dot(q, axes.up), z = dot(q, axes.forward);
    distance = std::max({distance, std::abs(x) / tx - z, std::abs(y) / ty - z});
  }
  Camera camera;
  camera.position = center - distance * axes.forward;
  camera.look_at = center;
  camera.up = up_for(axes.forward);
  camera.vertical_fov_deg = vertical_fov_deg;
  return camera;
}

Camera frame_from_position(const BoundingBox& box, const Vec3& eye, double vertical_fov_deg, double aspect,
                           bool fit_field_of_view) {
  Camera camera;
  camera.position = eye;
  camera.look_at = box.center();
  camera.up = up_for(camera.look_at - camera.position);
  camera.vertical_fov_deg = vertical_fov_deg;
  if (!fit_field_of_view || length(camera.look_at - eye) == 0) return camera;
  constexpr double kWidest_deg = 120.0;
  const ViewAxes axes(camera.look_at - eye);
  // The vertical half-field tangent each corner needs; a corner behind the eye needs
  // the widest field.
  double needed = 0;
  for (const Vec3& p : corners(box)) {
    const Vec3 q = p - eye;
    const double depth = dot(q, axes.forward);
    if (depth <= 0) {
      needed = std::tan(radians(0.5 * kWidest_deg));
      break;
    }
    needed = std::max({needed, std::abs(dot(q, axes.up)) / depth, std::abs(dot(q, axes.right)) / (depth * aspect)});
  }
  camera.vertical_fov_deg = std::clamp(degrees(2 * std::atan(needed / kFramingFill)), 0.01, kWidest_deg);
  return camera;
}

}  // namespace skylit
