// The quality figures of road lighting as EN 13201-3:2015 (and CIE 140) compute them,
// for the road a scene's `road_lighting` block describes, lit by the scene's lamps and
// shadowed by its geometry (occlusion rays from every grid point to every lamp, which
// the usual tools do not trace). docs/road-lighting.md gives the conventions.
//
// - Luminance grid: N points along the field (N = 10 for fields up to 30 m, else the
//   least N with spacing ≤ 3 m), first at half a spacing from its start; three across
//   each lane, at the sixths of its width. L = Σ_k I_k r(β_k, tan γ_k) / h_k² with the
//   road's r-table scaled by q0 / Q0 (road_reflection.h).
// - Observers: 60 m before the field, 1.5 m above the road, at the centre of each lane.
//   Each sees the whole grid: L_av, U_o = L_min/L_av; U_l = L_min/L_max along its own
//   lane's centre line. The figures reported are the worst over the observers.
// - Illuminance grid: the same rows; across the carriageway the least n ≥ 3 with
//   spacing ≤ 1.5 m. E_av, E_min.
// - Threshold increment: the observer (1.5 m, lane centre) looks along the road 1° down;
//   lamps more than 20° above the horizontal are screened by the car's roof, lamps
//   more than 500 m ahead or more than 60° off the line of sight are left out.
//   L_v = 10.0 Σ E_k / θ_k² (E_k the illuminance at the eye on the plane normal to the
//   line of sight, θ_k in degrees from it, at least 1.5°);
//   TI = 65 L_v / L_av^0.8 % (L_av ≤ 5 cd/m²; 95 L_v / L_av^1.05 above). The observer
//   starts where the first lamp ahead of the field's start is at 20° and moves forward
//   over one field length in the luminance grid's steps; the worst is reported (0 for
//   an unlit road, where TI is not defined).
// - Edge illuminance ratio: E_av on a strip just outside each edge over E_av on the
//   strip of equal width just inside it (width min(5 m, W/2)); the lower side.
#pragma once

#include <vector>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/scene/road_lighting_settings.h"
#include "skylit/scene/scene.h"

namespace skylit {

struct RoadLightingFigures {
  double average_luminance = 0;        // L_av, cd/m² (the lowest over the observers)
  double overall_uniformity = 0;       // U_o = L_min / L_av (lowest)
  double longitudinal_uniformity = 0;  // U_l (lowest over the lanes)
  double threshold_increment_pct = 0;  // TI, % (highest)
  double edge_illuminance_ratio = 0;   // R_EI (lower side)
  double average_illuminance = 0;      // E_av, lx
  double minimum_illuminance = 0;      // E_min, lx
  // The grids, for reports and tests: luminance per observer (lane), row-major
  // [along][across]; illuminance likewise.
  int rows = 0, luminance_columns = 0, illuminance_columns = 0;
  std::vector<std::vector<double>> luminance_by_observer;
  std::vector<double> illuminance;
};

// A point of the road's plane from coordinates along (from the field's start) and
// across (from the centre line, positive to the left of travel).
Vec3 road_point(const RoadLightingSettings& road, double along_m, double across_m);

// occluders: the scene's geometry (committed), or nullptr for none.
RoadLightingFigures compute_road_lighting(const RoadLightingSettings& road, const std::vector<SceneLight>& lights,
                                          const RayTracer* occluders);

}  // namespace skylit
