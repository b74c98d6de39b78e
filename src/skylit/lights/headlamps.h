// A car's headlamps (scene `cars`, docs/lights.md "Headlamps"): a pair placed from the
// car's position and heading, each with a low (passing) or high (driving) beam of a
// documented shape after UN ECE Regulation 112 (right-hand traffic), or with a
// photometric file's distribution.
#pragma once

#include <string>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/lights/luminaire.h"

namespace skylit {

enum class Beam { low, high };

// Where a car's lamps sit: 0.65 m above the road and 1.4 m apart, centre to centre, a
// mid-size car's (ECE R48 §6.2.4 allows 0.5–1.2 m high; the lamps' outer edges within
// 0.4 m of the car's sides).
inline constexpr double kHeadlampHeightM = 0.65;
inline constexpr double kHeadlampSpacingM = 1.4;

struct HeadlampPair {
  Vec3 left, right;  // the lamps' positions, as the driver sees left and right
  Vec3 forward;      // the car's horizontal heading (unit)
};

// `position` is the middle of the car's front at road level; `heading_deg` the direction
// it points, clockwise from north (as an azimuth).
HeadlampPair place_headlamps(const Vec3& position, double heading_deg);

// The beam's luminous intensity (cd) toward h degrees right of straight ahead and v
// degrees up, in the lamp's aimed frame (ECE's H–V; right-hand traffic):
//   low:  a body peaked at 1.5°R 1.2°D (20,000 cd; 4° wide to the left, 6° to the right,
//         1.2° high) and a wide foreground lobe (4000 cd at 2.5°D, 12° by 1.5°), cut
//         off above a line at 0.3°D on the left that rises at 15° right of the elbow to
//         0.64°U (a 0.4°-wide smooth step); above the cut-off a 200 cd veil.
//   high: 60,000 cd at H–V, 5° by 2° (Gaussian), with a 3000 cd, 15° by 4° lobe.
// Behind the lamp (more than 90° from straight ahead): nothing.
double headlamp_candela(Beam beam, double h_deg, double v_deg);

// The beam as a luminaire at `lamp_position` aimed along `forward`: the shape above
// tabulated on a (C, γ) grid about the forward axis (γ every 0.1° to 12°, then every 0.5°
// to 90°; C every 1°).
Luminaire headlamp_luminaire(const Vec3& lamp_position, const Vec3& forward, Beam beam);

// One test point of the regulation: where (degrees right, up), and the intensity it
// must have (0 for no bound).
struct BeamTestPoint {
  std::string name;
  double h_deg, v_deg;
  double min_cd, max_cd;  // max 0: no upper bound
};
// The points we build to (docs/lights.md gives the table and its source).
std::vector<BeamTestPoint> ece_r112_test_points(Beam beam);

}  // namespace skylit
