// Cameras placed to show given objects whole (the scene's `camera.frame`), so that a
// view takes one render to frame rather than several.
#pragma once

#include "skylit/geometry/triangle_mesh.h"
#include "skylit/scene/scene.h"

namespace skylit {

// How far toward the image's edge the framed objects reach, as a fraction of the half
// width or half height: a small margin around them.
inline constexpr double kFramingFill = 0.95;

// Looks at the box's centre from the direction (azimuth clockwise from north, elevation
// above the horizon, both seen from that centre), from the nearest distance at which
// every corner of the box lies within kFramingFill of the image's half width and half
// height (aspect = width / height). Straight down or up, the image's up is north.
Camera frame_from_direction(const BoundingBox& box, double from_azimuth_deg, double elevation_deg,
                            double vertical_fov_deg, double aspect);

// From a given eye, looks at the box's centre. With fit_field_of_view, the vertical field
// of view is the narrowest that holds every corner as above (at most 120°, and 120°
// when a corner is behind the eye); otherwise `vertical_fov_deg` is kept.
Camera frame_from_position(const BoundingBox& box, const Vec3& eye, double vertical_fov_deg, double aspect,
                           bool fit_field_of_view);

}  // namespace skylit
