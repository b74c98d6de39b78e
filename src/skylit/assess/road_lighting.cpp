// EN 13201-3 figures on the standard grids (road_lighting.h).
#include "skylit/assess/road_lighting.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

constexpr double kEyeHeightM = 1.5;
constexpr double kObserverDistanceM = 60;
constexpr double kRoofCutOffDeg = 20;  // lamps above it are screened by the car's roof
constexpr double kGlareReachM = 500;   // lamps farther ahead count for nothing
constexpr double kSightDownDeg = 1;
constexpr double kGlareMinAngleDeg = 1.5, kGlareMaxAngleDeg = 60;

Vec3 along_unit(const RoadLightingSettings& road) {
  const double az = radians(road.direction_deg);
  return {std::sin(az), std::cos(az), 0};
}

Vec3 left_unit(const RoadLightingSettings& road) {
  const Vec3 a = along_unit(road);
  return {-a.y, a.x, 0};
}

// Rows along the field: N = 10 up to 30 m, else the least N with spacing ≤ 3 m.
int row_count(double field_length_m) {
  return field_length_m <= 30 ? 10 : static_cast<int>(std::ceil(field_length_m / 3.0 - 1e-9));
}

// The points across a band [from, from + width]: n at the centres of equal parts.
std::vector<double> centres(double from, double width, int n) {
  std::vector<double> out;
  out.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) out.push_back(from + (i + 0.5) * width / n);
  return out;
}

int count_for_spacing(double width, double max_spacing, int at_least) {
  return std::max(at_least, static_cast<int>(std::ceil(width / max_spacing - 1e-9)));
}

bool lamp_visible(const RayTracer* occluders, const Vec3& from, const Vec3& lamp) {
  if (!occluders) return true;
  const Vec3 origin = offset_from_surface(from, {0, 0, 1});
  const Vec3 d = lamp - origin;
  const double len = length(d);
  if (!(len > 0)) return true;
  return !occluders->occluded(Ray{origin, d / len, 0.0, len * (1 - 1e-6)});
}

// What a lamp gives at a road point: its intensity toward it and the geometry.
struct LampAtPoint {
  double candela;
  Vec3 to_lamp;  // unit
  double distance_m;
};

// The scene's surface at a grid point: the top of kerbs, pavements and ramps within
// ±kSurfaceSearchM of the road's plane lifts the point onto it (an edge strip on a
// pavement is measured on its top, not inside it); anything else leaves it on the plane.
constexpr double kSurfaceSearchM = 0.5;

Vec3 on_surface(const Vec3& p, const RayTracer* occluders) {
  if (!occluders) return p;
  const Ray down{p + Vec3{0, 0, kSurfaceSearchM}, {0, 0, -1}, 0.0, 2 * kSurfaceSearchM};
  const std::optional<Hit> hit = occluders->intersect(down);
  // Only a surface facing up (a pavement's top, the road): the underside of a car parked
  // on the road is no place to measure, and the road below it stays where it is.
  return hit && hit->geometric_normal.z > 0 ? down.origin + hit->t * down.direction : p;
}

std::vector<LampAtPoint> lamps_at(const Vec3& road_plane_point, const std::vector<SceneLight>& lights,
                                  const RayTracer* occluders) {
  const Vec3 p = on_surface(road_plane_point, occluders);
  std::vector<LampAtPoint> out;
  for (const SceneLight& light : lights) {
    const Vec3 lamp = light.luminaire.position();
    const Vec3 d = lamp - p;
    const double dist = length(d);
    if (!(dist > 0) || d.z <= 0) continue;  // at or below the road: lights nothing on it
    const double candela = light.luminaire.intensity(-d);
    if (!(candela > 0) || !lamp_visible(occluders, p, lamp)) continue;
    out.push_back({candela, d / dist, dist});
  }
  return out;
}

double illuminance_at(const std::vector<LampAtPoint>& lamps) {
  double e = 0;
  for (const LampAtPoint& l : lamps) e += l.candela * l.to_lamp.z / (l.distance_m * l.distance_m);
  return e;
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

double average_illuminance_on(const RoadLightingSettings& road, const std::vector<SceneLight>& lights,
                              const RayTracer* occluders, const std::vector<double>& rows, double from, double width) {
  std::vector<double> e;
  for (double along : rows)
    for (double across : centres(from, width, count_for_spacing(width, 1.5, 2)))
      e.push_back(illuminance_at(lamps_at(road_point(road, along, across), lights, occluders)));
  return mean(e);
}

// TI for an observer at `across`, over the positions from the start to one field on.
double threshold_increment(const RoadLightingSettings& road, const std::vector<SceneLight>& lights,
                           const RayTracer* occluders, double across, double average_luminance, double step) {
  const Vec3 a = along_unit(road);
  const Vec3 eye_offset{0, 0, kEyeHeightM};
  // Where the first lamp at or past the field's start stands at the roof's cut-off.
  double start = std::numeric_limits<double>::infinity();
  double first_along = std::numeric_limits<double>::infinity();
  for (const SceneLight& light : lights) {
    const Vec3 rel = light.luminaire.position() - road.start;
    const double along = dot(rel, a), height = rel.z - kEyeHeightM;
    if (along >= -1e-9 && along < first_along && height > 0) {
      first_along = along;
      start = along - height / std::tan(radians(kRoofCutOffDeg));
    }
  }
  // No lamp ahead, or a road that is not lit at all (TI is relative to L_av): 0.
  if (!std::isfinite(start) || !(average_luminance > 0)) return 0;
  const Vec3 sight = normalize(a * std::cos(radians(kSightDownDeg)) - Vec3{0, 0, std::sin(radians(kSightDownDeg))});
  // cd m⁻² lx⁻¹ deg²: 9.86 (1 + (A/66.4)⁴) for an observer aged A = 23 (CIE 140:2019;
  // 10.0, the value of CIE 140-2000 and EN 13201-3).
  const double lv_coefficient = 9.86 * (1 + std::pow(23.0 / 66.4, 4));
  double worst = 0;
  for (int j = 0; j < row_count(road.field_length_m); ++j) {
    const Vec3 eye = road_point(road, start + j * step, across) + eye_offset;
    double veiling = 0;
    for (const SceneLight& light : lights) {
      const Vec3 d = light.luminaire.position() - eye;
      const double dist = length(d);
      const double ahead = dot(d, a);
      if (!(dist > 0) || ahead <= 0 || ahead > kGlareReachM) continue;
      if (degrees(std::asin(std::clamp(d.z / dist, -1.0, 1.0))) > kRoofCutOffDeg + 1e-9) continue;
      const Vec3 u = d / dist;
      const double cos_theta = std::clamp(dot(u, sight), -1.0, 1.0);
      const double theta_deg = degrees(std::acos(cos_theta));
      if (theta_deg > kGlareMaxAngleDeg) continue;  // the formula's range is 1.5°–60°
      if (!lamp_visible(occluders, eye, light.luminaire.position())) continue;
      const double e_eye = light.luminaire.intensity(-d) * cos_theta / (dist * dist);
      const double theta = std::max(theta_deg, kGlareMinAngleDeg);
      veiling += lv_coefficient * e_eye / (theta * theta);
    }
    const double ti = average_luminance <= 5 ? 65 * veiling / std::pow(average_luminance, 0.8)
                                             : 95 * veiling / std::pow(average_luminance, 1.05);
    worst = std::max(worst, ti);
  }
  return worst;
}

}  // namespace

Vec3 road_point(const RoadLightingSettings& road, double along_m, double across_m) {
  return road.start + along_unit(road) * along_m + left_unit(road) * across_m;
}

RoadLightingFigures compute_road_lighting(const RoadLightingSettings& road, const std::vector<SceneLight>& lights,
                                          const RayTracer* occluders) {
  RoadLightingFigures f;
  const int n_rows = row_count(road.field_length_m);
  const double step = road.field_length_m / n_rows;
  const std::vector<double> rows = centres(0, road.field_length_m, n_rows);
  const double lane_width = road.width_m / road.lanes;
  const double right_edge = -road.width_m / 2;
  std::vector<double> luminance_columns;
  for (int k = 0; k < road.lanes; ++k)
    for (double c : centres(right_edge + k * lane_width, lane_width, 3)) luminance_columns.push_back(c);
  const std::vector<double> illuminance_columns =
      centres(right_edge, road.width_m, count_for_spacing(road.width_m, 1.5, 3));
  f.rows = n_rows;
  f.luminance_columns = static_cast<int>(luminance_columns.size());
  f.illuminance_columns = static_cast<int>(illuminance_columns.size());

  // Luminance: the lamps seen from each point once; each observer only changes β.
  const RoadMaterial surface(road.r_table, road.q0);
  const Vec3 up{0, 0, 1};
  std::vector<std::vector<LampAtPoint>> lit;
  std::vector<Vec3> points;
  for (double along : rows)
    for (double across : luminance_columns) {
      points.push_back(road_point(road, along, across));
      lit.push_back(lamps_at(points.back(), lights, occluders));
    }
  f.average_luminance = f.overall_uniformity = f.longitudinal_uniformity = std::numeric_limits<double>::infinity();
  for (int k = 0; k < road.lanes; ++k) {
    const double lane_centre = right_edge + (k + 0.5) * lane_width;
    const Vec3 eye = road_point(road, -kObserverDistanceM, lane_centre) + Vec3{0, 0, kEyeHeightM};
    std::vector<double> l(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const Vec3 to_viewer = normalize(eye - points[i]);
      for (const LampAtPoint& lamp : lit[i]) {
        const double e = lamp.candela * lamp.to_lamp.z / (lamp.distance_m * lamp.distance_m);
        l[i] += surface.table_luminance_coefficient(up, lamp.to_lamp, to_viewer) * e;
      }
    }
    const double average = mean(l);
    const double minimum = *std::min_element(l.begin(), l.end());
    // U_l along this lane's centre line: the middle of its three columns.
    double lane_min = std::numeric_limits<double>::infinity(), lane_max = 0;
    for (int r = 0; r < n_rows; ++r) {
      const double v = l[static_cast<size_t>(r * f.luminance_columns + 3 * k + 1)];
      lane_min = std::min(lane_min, v);
      lane_max = std::max(lane_max, v);
    }
    f.average_luminance = std::min(f.average_luminance, average);
    f.overall_uniformity = std::min(f.overall_uniformity, average > 0 ? minimum / average : 0.0);
    f.longitudinal_uniformity = std::min(f.longitudinal_uniformity, lane_max > 0 ? lane_min / lane_max : 0.0);
    f.luminance_by_observer.push_back(std::move(l));
  }

  for (double along : rows)
    for (double across : illuminance_columns)
      f.illuminance.push_back(illuminance_at(lamps_at(road_point(road, along, across), lights, occluders)));
  f.average_illuminance = mean(f.illuminance);
  f.minimum_illuminance = *std::min_element(f.illuminance.begin(), f.illuminance.end());

  for (int k = 0; k < road.lanes; ++k)
    f.threshold_increment_pct = std::max(
        f.threshold_increment_pct,
        threshold_increment(road, lights, occluders, right_edge + (k + 0.5) * lane_width, f.average_luminance, step));

  const double strip = road.edge_strip_m > 0 ? road.edge_strip_m : std::min(5.0, road.width_m / 2);
  double ratio = std::numeric_limits<double>::infinity();
  for (int side : {-1, 1}) {
    const double edge = side * road.width_m / 2;
    const double outside = average_illuminance_on(road, lights, occluders, rows, side > 0 ? edge : edge - strip, strip);
    const double inside = average_illuminance_on(road, lights, occluders, rows, side > 0 ? edge - strip : edge, strip);
    ratio = std::min(ratio, inside > 0 ? outside / inside : 0.0);
  }
  f.edge_illuminance_ratio = ratio;
  return f;
}

}  // namespace skylit
