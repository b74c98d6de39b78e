// Street lamps in rows along a road (a scene's `lamp_rows`, docs/lights.md): where
// each luminaire of a row stands and how it is aimed, from the road's centre line,
// its width, the spacing, mounting height, overhang, tilt and arrangement.
#pragma once

#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

enum class LampArrangement {
  single_sided,  // all on one side
  opposite,      // in pairs facing each other across the road
  staggered,     // alternately right and left, `spacing_m` apart along the road
};

enum class RoadSide { right, left };  // of the direction in which the polyline runs

struct LampRowSettings {
  std::vector<Vec3> centre_line;  // ≥ 2 points; z is the road's height there
  double road_width_m = 7;
  double spacing_m = 30;  // between successive luminaires along the road
  double first_at_m = 0;  // the first luminaire's distance along the centre line
  double height_m = 8;    // of the luminaire above the road
  double overhang_m = 0;  // from the kerb over the road (negative: behind the kerb)
  double tilt_deg = 0;    // the nadir turned toward the road's far side
  LampArrangement arrangement = LampArrangement::single_sided;
  RoadSide side = RoadSide::right;  // single_sided: which; staggered: the first
};

struct LampPlacement {
  Vec3 position;
  Vec3 aim;             // the nadir
  double rotation_deg;  // about the aim, so that C0 runs along the road and C90 faces across it
};

// The luminaires of a row, in order along the centre line. Throws std::invalid_argument
// for a centre line shorter than two distinct points or a spacing ≤ 0.
std::vector<LampPlacement> place_lamp_row(const LampRowSettings& row);

}  // namespace skylit
