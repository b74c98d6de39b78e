// The camera block's projection, angles of view and lens shift (docs/scene-format.md,
// "camera"); each projection's angles have their own limits and defaults.
#include <string>

#include "skylit/io/scene/scene_parts.h"

namespace skylit {

void read_camera_projection(const JsonReader& j, Camera& camera) {
  const auto name = j.optional("projection");
  if (name) {
    const std::string p = name->one_of({"perspective", "fisheye_equidistant", "fisheye_equisolid",
                                        "fisheye_hemispherical", "cylindrical", "equirectangular"});
    camera.projection = p == "fisheye_equidistant"     ? Projection::fisheye_equidistant
                        : p == "fisheye_equisolid"     ? Projection::fisheye_equisolid
                        : p == "fisheye_hemispherical" ? Projection::fisheye_hemispherical
                        : p == "cylindrical"           ? Projection::cylindrical
                        : p == "equirectangular"       ? Projection::equirectangular
                                                       : Projection::perspective;
  }
  const bool panorama =
      camera.projection == Projection::cylindrical || camera.projection == Projection::equirectangular;
  if (auto h = j.optional("horizontal_fov_deg")) {
    if (!panorama) h->fail("horizontal_fov_deg is for the cylindrical and equirectangular projections");
    camera.horizontal_fov_deg = h->number_in(1, 360);
  }
  if (auto shift = j.optional("lens_shift")) {
    if (camera.projection != Projection::perspective) shift->fail("lens_shift is for the perspective projection");
    const std::vector<JsonReader> xy = shift->elements();
    if (xy.size() != 2) shift->fail_expected("[right, up], fractions of the image's width and height");
    camera.shift_x = xy[0].number_in(-2, 2);
    camera.shift_y = xy[1].number_in(-2, 2);
  }
  // The vertical angle of view: perspective's is read by read_camera; the others have
  // wider limits and their own defaults.
  const auto fov = j.optional("vertical_fov_deg");
  switch (camera.projection) {
    case Projection::perspective:
      return;
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
      camera.vertical_fov_deg = fov ? fov->number_in(1, 360) : 180.0;
      return;
    case Projection::fisheye_hemispherical:
      camera.vertical_fov_deg = fov ? fov->number_in(1, 180) : 180.0;
      return;
    case Projection::cylindrical:
      camera.vertical_fov_deg = fov ? fov->number_in(0.01, 179) : 60.0;
      return;
    case Projection::equirectangular:
      camera.vertical_fov_deg = fov ? fov->number_in(1, 180) : 180.0;
      return;
  }
}

}  // namespace skylit
