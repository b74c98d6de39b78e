// The camera as Radiance's view options, for the VIEW= line of a .hdr header, so that
// Radiance's tools (evalglare, pcomb, findglare) know which direction each pixel sees
// (Radiance's rpict(1) and ray/src/common/image.c: viewray).
#pragma once

#include <optional>
#include <string>

#include "skylit/scene/scene.h"

namespace skylit {

// "-vtv -vp x y z -vd dx dy dz -vu ux uy uz -vh H -vv V -vs s -vl l" for an image of
// width × height pixels: perspective -vtv (with lens shift -vs, -vl), equidistant
// fisheye -vta, hemispherical fisheye -vth, cylindrical -vtc. Empty for the
// projections Radiance has no view type for (equisolid fisheye, equirectangular) and
// for a hemispherical fisheye whose image is too wide for -vth's angles.
std::optional<std::string> radiance_view_options(const Camera& camera, int width, int height);

}  // namespace skylit
