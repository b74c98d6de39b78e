// The `road_lighting` part of a scene file: the road `skylit road` assesses
// (docs/road-lighting.md).
#include "skylit/io/scene/scene_parts.h"

namespace skylit {

RoadLightingSettings read_road_lighting(const JsonReader& j) {
  j.allow_only({"start", "direction_deg", "field_length_m", "width_m", "lanes", "r_table", "q0", "edge_strip_m"});
  RoadLightingSettings road;
  road.start = j.required("start").point_m();
  road.direction_deg = j.required("direction_deg").number_in(-360, 360);
  road.field_length_m = j.required("field_length_m").number_in(1, 1000);
  road.width_m = j.required("width_m").number_in(1, 100);
  if (auto lanes = j.optional("lanes")) road.lanes = lanes->integer_in(1, 12);
  const JsonReader name = j.required("r_table");
  road.r_table = RoadReflectionTable::standard(name.string());
  if (!road.r_table)
    name.fail("unknown r-table '" + name.string() + "'; known: " + RoadReflectionTable::standard_names());
  const auto q0 = j.optional("q0");
  road.q0 = q0 ? q0->number_in(0.01, 0.3) : road.r_table->nominal_q0();
  if (auto strip = j.optional("edge_strip_m")) road.edge_strip_m = strip->number_in(0.5, 50);
  return road;
}

}  // namespace skylit
