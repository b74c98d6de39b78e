// radiance_view_options (radiance_view.h). Radiance's angles are full angles in degrees
// across the image: -vh across the width, -vv across the height.
#include "skylit/io/image/radiance_view.h"

#include <cmath>
#include <cstdio>

#include "skylit/core/angles.h"

namespace skylit {

std::optional<std::string> radiance_view_options(const Camera& camera, int width, int height) {
  const double aspect = double(width) / height, v = camera.vertical_fov_deg;
  const char* type = nullptr;
  double vh = 0;
  switch (camera.projection) {
    case Projection::perspective:
      type = "-vtv";
      vh = degrees(2 * std::atan(std::tan(radians(v) / 2) * aspect));
      break;
    case Projection::fisheye_equidistant:  // angle linear in image distance, as ours
      type = "-vta";
      vh = v * aspect;
      break;
    case Projection::fisheye_hemispherical: {  // image distance ∝ sin θ: sin(vh/2) = aspect · sin(vv/2)
      const double s = aspect * std::sin(radians(v) / 2);
      if (s > 1) return std::nullopt;
      type = "-vth";
      vh = degrees(2 * std::asin(s));
      break;
    }
    case Projection::cylindrical:  // azimuth linear, vertical perspective, as ours
      type = "-vtc";
      vh = camera.horizontal_fov_deg;
      break;
    case Projection::fisheye_equisolid:
    case Projection::equirectangular:
      return std::nullopt;
  }
  const Vec3 d = normalize(camera.look_at - camera.position);
  const Vec3& p = camera.position;
  const Vec3& u = camera.up;
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "%s -vp %.9g %.9g %.9g -vd %.9g %.9g %.9g -vu %.9g %.9g %.9g -vh %.9g -vv %.9g",
                type, p.x, p.y, p.z, d.x, d.y, d.z, u.x, u.y, u.z, vh, v);
  std::string view = buffer;
  if (camera.projection == Projection::perspective && (camera.shift_x != 0 || camera.shift_y != 0)) {
    std::snprintf(buffer, sizeof buffer, " -vs %.9g -vl %.9g", camera.shift_x, camera.shift_y);
    view += buffer;
  }
  return view;
}

}  // namespace skylit
