// The road a scene's `road_lighting` block describes for the EN 13201-3 figures
// (assess/road_lighting.h, docs/road-lighting.md): a straight carriageway with its
// field of calculation, its lanes and its surface.
#pragma once

#include <memory>

#include "skylit/core/vec3.h"
#include "skylit/material/road_reflection.h"

namespace skylit {

struct RoadLightingSettings {
  // The carriageway's centre line where the field of calculation begins (z: the road's
  // height), and the direction of travel as an azimuth, clockwise from north.
  Vec3 start{0, 0, 0};
  double direction_deg = 0;
  // The field's length along the road: the spacing between two luminaires of a row.
  double field_length_m = 30;
  double width_m = 7;
  int lanes = 2;
  // The surface whose r-table gives the luminance (its Q0 scales the table).
  std::shared_ptr<const RoadReflectionTable> r_table;
  double q0 = 0.07;
  // The strips for the edge illuminance ratio; 0: min(5 m, half the width).
  double edge_strip_m = 0;
};

}  // namespace skylit
