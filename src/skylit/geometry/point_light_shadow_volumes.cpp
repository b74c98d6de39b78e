// A point light's shadow volumes (point_light_shadow_volumes.h): frusta from the light,
// found by the directions of their faces.
#include "skylit/geometry/point_light_shadow_volumes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "skylit/core/angles.h"
#include "skylit/geometry/shadow_casters.h"

namespace skylit {

namespace {

// Cells along each side of the cube map's faces: 64 makes cells 1.8° wide at a cube
// face's centre (measured on the Delft night scene: 32 and 128 were slower).
constexpr int kCellsPerSide = 64;

// The frustum behind a convex face seen from a point light at `light`, as its planes
// appended to `planes`, or false if it has none (degenerate, or edge-on to the light):
// a side through the light and each edge, then the cap (the face's plane).
bool make_frustum(const ConvexFace& face, const Vec3& centroid, const Vec3& light, std::vector<HalfSpace>& planes) {
  const size_t first = planes.size();
  const size_t n = face.corners.size();
  for (size_t i = 0; i < n; ++i) {
    // As for prisms, the plane through the light and an edge is built from the edge's
    // ends in one canonical order, so two faces sharing the edge get it bit for bit.
    Vec3 a = face.corners[i], b = face.corners[(i + 1) % n];
    if (lexicographic_less(b, a)) std::swap(a, b);
    const Vec3 m = cross(a - light, b - light);
    const double side = dot(m, centroid - light);
    if (!(side != 0)) {
      planes.resize(first);
      return false;
    }
    const double sign = side > 0 ? 1.0 : -1.0;
    planes.push_back({sign * m, sign * dot(m, light)});
  }
  const double facing = dot(face.normal, light - face.corners[0]);
  if (!(facing != 0)) {
    planes.resize(first);
    return false;
  }
  const Vec3 away = facing > 0 ? -face.normal : face.normal;  // from the face away from the light
  planes.push_back({away, dot(away, face.corners[0])});
  return true;
}

// Whether the sphere (centre, radius) lies wholly outside the cone of half-angle
// max_gamma_deg about the unit `aim` from `apex` (conservative: false when unsure).
bool outside_cone(const Vec3& centre, double radius, const Vec3& apex, const Vec3& aim, double max_gamma_deg) {
  if (!(max_gamma_deg < 180)) return false;
  const Vec3 to_centre = centre - apex;
  const double distance = length(to_centre);
  if (!(distance > radius)) return false;
  const double angle = std::acos(std::clamp(dot(to_centre, aim) / distance, -1.0, 1.0));
  return angle - std::asin(radius / distance) > max_gamma_deg * kPi / 180;
}

}  // namespace

std::vector<ShadowCasterFaces> shadow_caster_faces(const std::vector<const TriangleMesh*>& meshes) {
  std::vector<ShadowCasterFaces> out;
  out.reserve(meshes.size());
  for (size_t id = 0; id < meshes.size(); ++id) {
    const TriangleMesh& mesh = checked_mesh(meshes, id, "PointLightShadowVolumes");
    out.push_back({convex_faces(mesh), mesh.triangles.empty() ? 0 : casting_side(mesh)});
  }
  return out;
}

PointLightShadowVolumes::PointLightShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                                                 const Vec3& aim, double max_gamma_deg, double reach_m)
    : PointLightShadowVolumes(shadow_caster_faces(meshes), light, aim, max_gamma_deg, reach_m) {}

PointLightShadowVolumes::PointLightShadowVolumes(const std::vector<ShadowCasterFaces>& meshes, const Vec3& light,
                                                 const Vec3& aim, double max_gamma_deg, double reach_m)
    : light_(light), cells_(light, kCellsPerSide) {
  if (!is_finite(light)) throw std::invalid_argument("PointLightShadowVolumes: the light's position must be finite");
  scale_ = std::max(1.0, max_abs(light));
  for (const ShadowCasterFaces& mesh : meshes) {
    // A closed surface is left through faces facing the light, as for the sun.
    const int keep = mesh.casting_side;
    for (const ConvexFace& face : mesh.faces) {
      if (keep != 0 && !(keep * dot(face.normal, light - face.corners[0]) > 0)) continue;
      Vec3 centre{0, 0, 0};
      for (const Vec3& c : face.corners) centre += c;
      centre = centre / static_cast<double>(face.corners.size());
      double radius = 0;
      for (const Vec3& c : face.corners) radius = std::max(radius, length(c - centre));
      if (outside_cone(centre, radius, light, aim, max_gamma_deg)) continue;
      if (length(centre - light) - radius > reach_m) continue;
      const auto first = static_cast<uint32_t>(planes_.size());
      if (!make_frustum(face, centre, light, planes_)) continue;
      cells_.add(static_cast<uint32_t>(frusta_.size()), face);
      frusta_.push_back({first, static_cast<uint32_t>(face.corners.size())});
      for (const Vec3& c : face.corners) scale_ = std::max(scale_, max_abs(c));
    }
  }
  cells_.finish();
}

std::vector<Interval> PointLightShadowVolumes::lit_intervals(const Ray& ray, double t_min, double t_max) const {
  std::vector<Interval> out;
  lit_intervals(ray, t_min, t_max, out);
  return out;
}

void PointLightShadowVolumes::lit_intervals(const Ray& ray, double t_min, double t_max,
                                            std::vector<Interval>& out) const {
  // Which frusta this query has clipped: a face spans many cells. Marked with the
  // query's number, so that the marks need no clearing.
  thread_local std::vector<uint32_t> clipped;
  thread_local uint32_t query = 0;
  auto collect_shadows = [&](const Vec3& o, const Vec3& dir, std::vector<Interval>& shadows) {
    const auto clip = [&](uint32_t i) {
      double lo = t_min, hi = t_max;
      if (clip_to_half_spaces(&planes_[frusta_[i].first_plane], frusta_[i].sides + 1, o, dir, lo, hi))
        shadows.push_back({lo, hi});
    };
    // An unbounded piece has no farthest point to compare: every frustum.
    if (!std::isfinite(t_min) || !std::isfinite(t_max)) {
      for (uint32_t i = 0; i < frusta_.size(); ++i) clip(i);
      return;
    }
    if (clipped.size() < frusta_.size()) clipped.resize(frusta_.size(), 0);
    if (++query == 0) {
      std::fill(clipped.begin(), clipped.end(), 0);
      query = 1;
    }
    for (const uint32_t i : cells_.everywhere()) {
      clipped[i] = query;
      clip(i);
    }
    const std::vector<uint32_t>& items = cells_.items();
    const std::vector<float>& nearest = cells_.nearest_m();
    cells_.walk(o, dir, t_min, t_max, [&](const LightDirectionCells::Cell& cell, double t_a, double t_b) {
      // The piece's part in the cell: its farthest point from the light is an end
      // (distance is convex along it), its lowest an end too.
      const Vec3 a = o + dir * t_a - light_, b = o + dir * t_b - light_;
      // Padded so that rounding never drops a frustum the exact clip would keep.
      const double padding = kRelativeShadowBoundPadding * scale_;
      const double farthest = std::max(length(a), length(b)) + padding;
      if (light_.z + std::min(a.z, b.z) > cell.top_z + padding) return;
      // Nearest first: the faces from the first beyond the piece on lie behind it.
      for (uint32_t k = cell.begin; k < cell.end && nearest[k] <= farthest; ++k) {
        const uint32_t i = items[k];
        if (clipped[i] == query) continue;
        clipped[i] = query;
        clip(i);
      }
    });
  };
  lit_intervals_from_shadows(ray, t_min, t_max, scale_, frusta_.empty(), collect_shadows, out);
}

}  // namespace skylit
