// A point light's shadow volumes (point_light_shadow_volumes.h): frusta from the light,
// tested group by group behind cones.
#include "skylit/geometry/point_light_shadow_volumes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "skylit/core/angles.h"
#include "skylit/geometry/shadow_casters.h"

namespace skylit {

namespace {

// The hierarchy's leaves hold at most this many frusta.
constexpr uint32_t kFrustaPerLeaf = 4;

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

// A casting face's frustum (planes [first_plane, first_plane + sides + 1) of the
// constructor's list) with the bounding sphere of its corners.
struct PointLightShadowVolumes::Caster {
  uint32_t first_plane, sides;
  Vec3 centre;
  double radius;
  Vec3 direction;  // unit, from the light toward the centre (ordering only)
  double top_z;    // the highest corner's z when the light is above every corner, else +∞
};

PointLightShadowVolumes::PointLightShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                                                 const Vec3& aim, double max_gamma_deg, double reach_m)
    : PointLightShadowVolumes(shadow_caster_faces(meshes), light, aim, max_gamma_deg, reach_m) {}

PointLightShadowVolumes::PointLightShadowVolumes(const std::vector<ShadowCasterFaces>& meshes, const Vec3& light,
                                                 const Vec3& aim, double max_gamma_deg, double reach_m)
    : light_(light) {
  if (!is_finite(light)) throw std::invalid_argument("PointLightShadowVolumes: the light's position must be finite");
  scale_ = std::max(1.0, max_abs(light));
  std::vector<Caster> casters;
  std::vector<HalfSpace> planes;
  for (const ShadowCasterFaces& mesh : meshes) {
    // A closed surface is left through faces facing the light, as for the sun.
    const int keep = mesh.casting_side;
    for (const ConvexFace& face : mesh.faces) {
      if (keep != 0 && !(keep * dot(face.normal, light - face.corners[0]) > 0)) continue;
      Vec3 centre{0, 0, 0};
      double top = -std::numeric_limits<double>::infinity();
      for (const Vec3& c : face.corners) {
        centre += c;
        top = std::max(top, c.z);
      }
      centre = centre / static_cast<double>(face.corners.size());
      double radius = 0;
      for (const Vec3& c : face.corners) radius = std::max(radius, length(c - centre));
      if (outside_cone(centre, radius, light, aim, max_gamma_deg)) continue;
      const double distance = length(centre - light);
      if (distance - radius > reach_m) continue;
      // Lit from above, the frustum runs down from the face: nothing in it is higher
      // than its highest corner.
      Caster caster{static_cast<uint32_t>(planes.size()),
                    static_cast<uint32_t>(face.corners.size()),
                    centre,
                    radius,
                    distance > 0 ? (centre - light) / distance : Vec3{0, 0, 1},
                    top < light.z ? top : std::numeric_limits<double>::infinity()};
      if (!make_frustum(face, centre, light, planes)) continue;
      casters.push_back(caster);
      for (const Vec3& c : face.corners) scale_ = std::max(scale_, max_abs(c));
    }
  }
  if (casters.empty()) return;
  nodes_.reserve(2 * casters.size() / kFrustaPerLeaf + 1);
  build(casters, 0, static_cast<uint32_t>(casters.size()));
  // The planes in the hierarchy's order.
  frusta_.reserve(casters.size());
  planes_.reserve(planes.size());
  for (const Caster& caster : casters) {
    frusta_.push_back({static_cast<uint32_t>(planes_.size()), caster.sides});
    planes_.insert(planes_.end(), planes.begin() + caster.first_plane,
                   planes.begin() + caster.first_plane + caster.sides + 1);
  }
}

uint32_t PointLightShadowVolumes::build(std::vector<Caster>& casters, uint32_t begin, uint32_t end) {
  // The node's bounding sphere: around the mean of its casters' centres.
  Vec3 centre{0, 0, 0};
  double top_z = -std::numeric_limits<double>::infinity();
  double lo[3] = {2, 2, 2}, hi[3] = {-2, -2, -2};  // the directions' bounding box
  for (uint32_t i = begin; i < end; ++i) {
    centre += casters[i].centre;
    top_z = std::max(top_z, casters[i].top_z);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], casters[i].direction[k]);
      hi[k] = std::max(hi[k], casters[i].direction[k]);
    }
  }
  centre = centre / static_cast<double>(end - begin);
  double radius = 0;
  for (uint32_t i = begin; i < end; ++i)
    radius = std::max(radius, length(casters[i].centre - centre) + casters[i].radius);
  const double distance = length(centre - light_);
  // Padded so that rounding never drops a frustum the exact clip would keep.
  radius = radius * (1 + 1e-9) + kRelativeShadowBoundPadding * scale_;
  Node node{Vec3{0, 0, 1}, 2.0, 0.0, 0.0, top_z + kRelativeShadowBoundPadding * scale_, begin, end, 0};
  if (distance > radius) {
    node.axis = (centre - light_) / distance;
    node.sin_half = radius / distance;
    node.cos_half = std::sqrt(std::max(0.0, 1 - node.sin_half * node.sin_half));
    node.nearest_m = distance - radius;
  }
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.push_back(node);
  if (end - begin <= kFrustaPerLeaf) return index;
  // Split at the median along the widest spread of the casters' directions, so that
  // children see narrow cones.
  const double spread[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  const int axis = spread[0] >= spread[1] && spread[0] >= spread[2] ? 0 : (spread[1] >= spread[2] ? 1 : 2);
  const uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(casters.begin() + begin, casters.begin() + middle, casters.begin() + end,
                   [axis](const Caster& a, const Caster& b) { return a.direction[axis] < b.direction[axis]; });
  build(casters, begin, middle);
  const uint32_t second = build(casters, middle, end);
  nodes_[index].second = second;
  return index;
}

bool PointLightShadowVolumes::may_meet(const Node& node, const Vec3& plane_normal, double plane_normal_length,
                                       const Vec3& near, const Vec3& far, double far_distance, double lowest_z) const {
  // The piece passes above every frustum (ground surfaces under a lamp).
  if (lowest_z > node.top_z) return false;
  if (!(node.sin_half < 1)) return true;
  // Every point of the piece is nearer to the light than the node's casters.
  if (far_distance < node.nearest_m) return false;
  if (!(plane_normal_length > 0)) return true;
  // The plane of the view ray and the light misses the cone.
  const double off_plane = dot(node.axis, plane_normal);
  if (std::abs(off_plane) > node.sin_half * plane_normal_length) return false;
  // The cone meets the plane but perhaps not the arc of the piece's directions: when the
  // axis's projection lies outside the arc's wedge (by more than rounding), the arc's
  // nearest direction to the axis is an end's.
  const double near_length = length(near), far_length = length(far);
  const bool outside_wedge = dot(cross(near, node.axis), plane_normal) < -1e-9 * near_length * plane_normal_length ||
                             dot(cross(node.axis, far), plane_normal) < -1e-9 * far_length * plane_normal_length;
  if (!outside_wedge) return true;
  const double cos_margin = node.cos_half - 1e-9;
  return dot(node.axis, near) >= cos_margin * near_length || dot(node.axis, far) >= cos_margin * far_length;
}

std::vector<Interval> PointLightShadowVolumes::lit_intervals(const Ray& ray, double t_min, double t_max) const {
  std::vector<Interval> out;
  lit_intervals(ray, t_min, t_max, out);
  return out;
}

void PointLightShadowVolumes::lit_intervals(const Ray& ray, double t_min, double t_max,
                                            std::vector<Interval>& out) const {
  auto collect_shadows = [&](const Vec3& o, const Vec3& dir, std::vector<Interval>& shadows) {
    // The piece's ends seen from the light, and the normal of the plane the view ray and
    // the light span (oriented from `near` toward `far`).
    // With no finite start, or a piece (nearly) in line with the light, whose plane
    // rounding would tilt, every node is visited.
    const bool bounded = std::isfinite(t_max);
    const Vec3 near = std::isfinite(t_min) ? o + dir * t_min - light_ : Vec3{0, 0, 0};
    const Vec3 far = bounded ? o + dir * t_max - light_ : dir;
    // The piece's farthest point from the light is an end (distance is convex along it).
    const double far_distance =
        bounded && std::isfinite(t_min) ? std::max(length(near), length(far)) : std::numeric_limits<double>::infinity();
    const Vec3 normal = cross(near, far);
    double normal_length = length(normal);
    if (!(normal_length > 1e-9 * length(near) * length(far))) normal_length = 0;
    const double lowest_z =
        bounded && std::isfinite(t_min) ? light_.z + std::min(near.z, far.z) : -std::numeric_limits<double>::infinity();
    uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (!may_meet(node, normal, normal_length, near, far, far_distance, lowest_z)) continue;
      if (node.second == 0) {
        for (uint32_t i = node.begin; i < node.end; ++i) {
          double lo = t_min, hi = t_max;
          if (clip_to_half_spaces(&planes_[frusta_[i].first_plane], frusta_[i].sides + 1, o, dir, lo, hi))
            shadows.push_back({lo, hi});
        }
        continue;
      }
      stack[top++] = node.second;
      stack[top++] = static_cast<uint32_t>(&node - nodes_.data()) + 1;
    }
  };
  lit_intervals_from_shadows(ray, t_min, t_max, scale_, frusta_.empty(), collect_shadows, out);
}

}  // namespace skylit
