// A point light's shadow volumes (point_light_shadow_volumes.h): frusta from the light,
// tested group by group behind cones.
#include "skylit/geometry/point_light_shadow_volumes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skylit/core/angles.h"
#include "skylit/geometry/shadow_casters.h"

namespace skylit {

namespace {

// The frusta are tested in groups of at most this many, each behind a cone.
constexpr size_t kFrustaPerGroup = 4;

// The frustum behind triangle (p, q, r) seen from a point light at `light`, or false if
// it has no volume (degenerate, or edge-on to the light). Same face order as a prism:
// three sides through the light and an edge, then the cap (the triangle's plane).
bool make_frustum(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& light, ShadowVolume& frustum) {
  const Vec3 corners[3] = {p, q, r};
  for (int i = 0; i < 3; ++i) {
    // As for prisms, the plane through the light and an edge is built from the edge's
    // ends in one canonical order, so two triangles sharing the edge get it bit for bit.
    Vec3 a = corners[i], b = corners[(i + 1) % 3];
    if (lexicographic_less(b, a)) std::swap(a, b);
    const Vec3 m = cross(a - light, b - light);
    const double side = dot(m, corners[(i + 2) % 3] - light);
    if (!(side != 0)) return false;
    const double sign = side > 0 ? 1.0 : -1.0;
    frustum.faces[i] = {sign * m, sign * dot(m, light)};
  }
  const Vec3 n = cross(q - p, r - p);
  const double facing = dot(n, light - p);
  if (!(facing != 0)) return false;
  const Vec3 away = facing > 0 ? -n : n;  // from the triangle away from the light
  frustum.faces[3] = {away, dot(away, p)};
  return true;
}

// Whether triangle (p, q, r) lies wholly outside the cone of half-angle max_gamma_deg
// about the unit `aim` from `apex`, by its bounding sphere (conservative: false when
// unsure).
bool outside_cone(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& apex, const Vec3& aim,
                  double max_gamma_deg) {
  if (!(max_gamma_deg < 180)) return false;
  const Vec3 centre = (p + q + r) / 3.0;
  const double radius = std::max({length(p - centre), length(q - centre), length(r - centre)});
  const Vec3 to_centre = centre - apex;
  const double distance = length(to_centre);
  if (!(distance > radius)) return false;
  const double angle = std::acos(std::clamp(dot(to_centre, aim) / distance, -1.0, 1.0));
  return angle - std::asin(radius / distance) > max_gamma_deg * kPi / 180;
}

}  // namespace

PointLightShadowVolumes::PointLightShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                                                 const Vec3& aim, double max_gamma_deg)
    : light_(light) {
  if (!is_finite(light)) throw std::invalid_argument("PointLightShadowVolumes: the light's position must be finite");
  scale_ = std::max(1.0, max_abs(light));
  for (size_t id = 0; id < meshes.size(); ++id) {
    const TriangleMesh& mesh = checked_mesh(meshes, id, "PointLightShadowVolumes");
    if (mesh.triangles.empty()) continue;
    // A closed surface is left through triangles facing the light, as for the sun.
    const int keep = casting_side(mesh);
    std::vector<Vec3> corners;  // of the group being filled
    auto close_group = [&] {
      const uint32_t begin = groups_.empty() ? 0 : groups_.back().end;
      const uint32_t end = static_cast<uint32_t>(frusta_.size());
      if (end == begin) return;
      Vec3 centre{0, 0, 0};
      for (const Vec3& c : corners) centre += c;
      centre = centre / static_cast<double>(corners.size());
      double radius = 0;
      for (const Vec3& c : corners) radius = std::max(radius, length(c - centre));
      const double distance = length(centre - light);
      // Padded so that rounding never drops a frustum the exact clip would keep.
      radius = radius * (1 + 1e-9) + kRelativeShadowBoundPadding * scale_;
      groups_.push_back({distance > radius ? (centre - light) / distance : Vec3{0, 0, 1},
                         distance > radius ? radius / distance : 2.0, begin, end});
      corners.clear();
    };
    for (const auto& t : mesh.triangles) {
      const Vec3 &p = mesh.vertices[t[0]], &q = mesh.vertices[t[1]], &r = mesh.vertices[t[2]];
      if (keep != 0 && !(keep * dot(cross(q - p, r - p), light - p) > 0)) continue;
      if (outside_cone(p, q, r, light, aim, max_gamma_deg)) continue;
      ShadowVolume frustum;
      if (!make_frustum(p, q, r, light, frustum)) continue;
      frusta_.push_back(frustum);
      corners.insert(corners.end(), {p, q, r});
      scale_ = std::max({scale_, max_abs(p), max_abs(q), max_abs(r)});
      if (corners.size() >= 3 * kFrustaPerGroup) close_group();
    }
    close_group();
  }
}

std::vector<Interval> PointLightShadowVolumes::lit_intervals(const Ray& ray, double t_min, double t_max) const {
  std::vector<Interval> out;
  lit_intervals(ray, t_min, t_max, out);
  return out;
}

void PointLightShadowVolumes::lit_intervals(const Ray& ray, double t_min, double t_max,
                                            std::vector<Interval>& out) const {
  auto collect_shadows = [&](const Vec3& o, const Vec3& dir, std::vector<Interval>& shadows) {
    // The view ray and the light span a plane; a group's cone that the plane misses
    // (its axis further than the cone's half-angle from the plane) holds no frustum the
    // ray can meet.
    const Vec3 normal = cross(o - light_, dir);
    const double normal_length = length(normal);
    for (const Group& g : groups_) {
      if (g.sin_half < 1 && normal_length > 0 && std::abs(dot(g.axis, normal)) > g.sin_half * normal_length) continue;
      for (uint32_t i = g.begin; i < g.end; ++i) {
        double lo = t_min, hi = t_max;
        if (clip_to_volume(frusta_[i], o, dir, lo, hi)) shadows.push_back({lo, hi});
      }
    }
  };
  lit_intervals_from_shadows(ray, t_min, t_max, scale_, frusta_.empty(), collect_shadows, out);
}

}  // namespace skylit
