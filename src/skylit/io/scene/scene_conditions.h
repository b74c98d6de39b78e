// The conditions of a render said in words and numbers, one row per subject: site,
// time, sun, weather, atmosphere, sky, fog, clouds, lights, camera and lens, image. For the HTML
// report (docs/report.md), where they stand beside the pictures they explain.
#pragma once

#include <string>
#include <vector>

#include "skylit/scene/scene.h"

namespace skylit {

struct ConditionRow {
  std::string subject;      // "Sun"
  std::string description;  // "altitude 35.2°, azimuth 182.1° (clockwise from north)"
};

std::vector<ConditionRow> scene_conditions(const Scene& scene);

}  // namespace skylit
