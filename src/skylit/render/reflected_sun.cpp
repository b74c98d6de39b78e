// ReflectedSun (reflected_sun.h).
#include "skylit/render/reflected_sun.h"

#include <cmath>
#include <map>
#include <utility>

#include "skylit/geometry/plane_groups.h"
#include "skylit/material/microfacet.h"
#include "skylit/material/reflection.h"
#include "skylit/material/reflection_sampling.h"

namespace skylit {

namespace {

// Triangles are one plane when they agree within geometry/plane_groups.h's tolerance
// (rounded_plane), here of one material.
using PlaneKey = std::pair<uint32_t, std::array<long long, 4>>;

PlaneKey plane_key(uint32_t material, Vec3 normal, double offset) { return {material, rounded_plane(normal, offset)}; }

// Whether a ray can meet the box (slab test). The box of a flat facet is flat: it is
// padded by kBoxPadM on every axis so the test stays robust.
constexpr double kBoxPadM = 1e-3;
bool ray_meets_box(const Vec3& origin, const Vec3& direction, const BoundingBox& box) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double o = origin[axis], d = direction[axis];
    const double lo = box.lo[axis] - kBoxPadM, hi = box.hi[axis] + kBoxPadM;
    if (std::abs(d) < 1e-15) {
      if (o < lo || o > hi) return false;
      continue;
    }
    double a = (lo - o) / d, b = (hi - o) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

bool reflects_sun(const Material& material) {
  return (std::holds_alternative<CookTorranceMaterial>(material) || std::holds_alternative<GlassMaterial>(material)) &&
         !is_broad_lobe(material);
}

}  // namespace

bool is_broad_lobe(const Material& material) {
  return has_specular(material) && specular_roughness(material) >= kBroadLobeRoughness;
}

ReflectedSun::ReflectedSun(const Scene& scene, const RayTracer& tracer, const Vec3& to_sun, SunAt sun_at)
    : tracer_(tracer), to_sun_(to_sun), sun_at_(std::move(sun_at)) {
  triangle_group_.resize(scene.objects.size());
  if (to_sun_.z <= 0) return;  // the sun is down: nothing to reflect
  std::map<PlaneKey, int32_t> group_of_plane;
  std::map<PlaneKey, int32_t> class_of_orientation;
  std::vector<uint32_t> class_material;
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    const TriangleMesh& mesh = object.mesh;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const uint32_t material = object.material_of(t);
      if (!reflects_sun(scene.materials[material].material)) continue;
      const std::optional<TrianglePlane> triangle = triangle_plane(mesh, t);
      if (!triangle) continue;
      const Vec3& n = triangle->normal;
      const auto [group_it, new_group] =
          group_of_plane.try_emplace(plane_key(material, n, triangle->offset), static_cast<int32_t>(groups_.size()));
      if (new_group) {
        groups_.push_back({n, triangle->offset});
        const auto [class_it, new_class] =
            class_of_orientation.try_emplace(plane_key(material, n, 0), static_cast<int32_t>(classes_.size()));
        if (new_class) {
          classes_.push_back({n, {}, false, {}});
          class_material.push_back(material);
        }
        class_of_group_.push_back(class_it->second);
      }
      OrientationClass& orientation = classes_[static_cast<size_t>(class_of_group_[group_it->second])];
      for (const uint32_t v : mesh.triangles[t]) orientation.box.add(mesh.vertices[v]);
      if (triangle_group_[o].empty()) triangle_group_[o].assign(mesh.triangles.size(), -1);
      triangle_group_[o][t] = group_it->second;
    }
  }
  // Each plane reflects from the side the sun lights; a class's nodes follow from its
  // material. The planes of a class share its normal to 1e-4, so they turn with it.
  for (size_t g = 0; g < groups_.size(); ++g) {
    if (dot(classes_[static_cast<size_t>(class_of_group_[g])].normal, to_sun_) < 0) {
      groups_[g].normal = -groups_[g].normal;
      groups_[g].offset = -groups_[g].offset;
    }
  }
  for (size_t c = 0; c < classes_.size(); ++c) {
    OrientationClass& orientation = classes_[c];
    if (dot(orientation.normal, to_sun_) < 0) orientation.normal = -orientation.normal;
    add_nodes(orientation, scene.materials[class_material[c]].material);
    has_mirrors_ = has_mirrors_ || (orientation.mirror && !orientation.nodes.empty());
    has_rough_ = has_rough_ || (!orientation.mirror && !orientation.nodes.empty());
  }
  // The classes with nodes, mirrors and rough apart, in trees of their boxes and cones.
  for (const bool mirrors : {true, false}) {
    std::vector<BoxCone> items;
    std::vector<int32_t>& classes = mirrors ? mirror_classes_ : rough_classes_;
    for (size_t c = 0; c < classes_.size(); ++c) {
      const OrientationClass& orientation = classes_[c];
      if (orientation.mirror != mirrors || orientation.nodes.empty()) continue;
      // The cone about the nodes' mean direction that holds them all.
      BoxCone item{orientation.box, {0, 0, 0}, 1};
      for (const Node& node : orientation.nodes) item.axis += node.toward;
      item.axis = length(item.axis) > 1e-9 ? normalize(item.axis) : orientation.nodes.front().toward;
      for (const Node& node : orientation.nodes)
        item.cos_spread = std::min(item.cos_spread, dot(node.toward, item.axis));
      items.push_back(item);
      classes.push_back(static_cast<int32_t>(c));
    }
    // ray_meets_box's pad on each axis is √3 of it along the diagonal.
    (mirrors ? mirror_tree_ : rough_tree_) = ConeTree(items, std::sqrt(3.0) * kBoxPadM);
  }
}

void ReflectedSun::add_nodes(OrientationClass& orientation, const Material& material) const {
  const Vec3& n = orientation.normal;
  const Vec3& s = to_sun_;
  const double cos_sun = dot(n, s);
  if (!(cos_sun > 1e-6)) return;  // the sun grazes the plane or lights its back
  if (const std::optional<Reflectance> mirror = mirror_reflectance(material, n, s)) {
    orientation.mirror = true;
    orientation.nodes.push_back({-(2 * cos_sun * n - s), mirror->spectrum()});
    return;
  }
  const double m = specular_roughness(material);
  if (!(m > 0)) return;
  Vec3 t, b;
  orthonormal_frame(n, t, b);
  constexpr int kNodes = kLobeRings * kLobeAzimuths;
  for (int ring = 0; ring < kLobeRings; ++ring) {
    // tan²θ_h = −m² ln(1 − u) draws θ_h with density D(h)(n·h) (Walter et al. 2007, §5.3);
    // u at the middle of each ring's equal share.
    const double u = (ring + 0.5) / kLobeRings;
    const double tan2 = -m * m * std::log1p(-u);
    const double cos_h = 1 / std::sqrt(1 + tan2), sin_h = std::sqrt(std::max(0.0, 1 - cos_h * cos_h));
    for (int k = 0; k < kLobeAzimuths; ++k) {
      // Alternate rings turned by half a step, so the nodes do not line up radially.
      const double phi = 2 * kPi * (k + 0.5 * (ring % 2)) / kLobeAzimuths;
      const Vec3 h = cos_h * n + sin_h * (std::cos(phi) * t + std::sin(phi) * b);
      const double sun_half = dot(s, h);
      if (!(sun_half > 0)) continue;
      const Vec3 r = 2 * sun_half * h - s;
      if (!(dot(n, r) > 0)) continue;
      // The density of the reflected direction r: D(h)(n·h) / (4 s·h).
      const double pdf = beckmann_distribution(cos_h, m) * cos_h / (4 * sun_half);
      if (!(pdf > 0)) continue;
      const Spectrum f_cos = specular_reflection(material, n, s, r).per_sr;
      orientation.nodes.push_back({-r, f_cos * static_cast<float>(1.0 / (kNodes * pdf))});
    }
  }
}

Irradiance ReflectedSun::from(const Vec3& position, const Vec3& normal, bool mirrors) const {
  Spectrum sum(0.0f);
  const Vec3 origin = offset_from_surface(position, normal);
  // Each class's node rays go to the tracer together: they share the origin and lie
  // within one lobe, a coherent packet.
  thread_local std::vector<Ray> rays;
  thread_local std::vector<const Node*> ray_nodes;
  thread_local std::vector<std::optional<Hit>> hits;
  const std::vector<int32_t>& classes = mirrors ? mirror_classes_ : rough_classes_;
  (mirrors ? mirror_tree_ : rough_tree_).visit(origin, [&](size_t item) {
    const auto c = static_cast<size_t>(classes[item]);
    const OrientationClass& orientation = classes_[c];
    rays.clear();
    ray_nodes.clear();
    for (const Node& node : orientation.nodes) {
      const double cos_point = dot(normal, node.toward);
      if (!(cos_point > 0) || !ray_meets_box(origin, node.toward, orientation.box)) continue;
      rays.push_back(Ray{origin, node.toward});
      ray_nodes.push_back(&node);
    }
    if (rays.empty()) return;
    tracer_.intersect(rays, hits);
    for (size_t r = 0; r < rays.size(); ++r) {
      const Node& node = *ray_nodes[r];
      const double cos_point = dot(normal, node.toward);
      const std::optional<Hit>& hit = hits[r];
      if (!hit) continue;
      const std::vector<int32_t>& groups_of_mesh = triangle_group_[hit->mesh_id];
      if (groups_of_mesh.empty()) continue;
      const int32_t g = groups_of_mesh[hit->triangle];
      if (g < 0 || class_of_group_[static_cast<size_t>(g)] != static_cast<int32_t>(c)) continue;
      // Only the lit side of the plane sees its reflection.
      const Group& group = groups_[static_cast<size_t>(g)];
      if (dot(group.normal, origin) - group.offset <= 0) continue;
      const Irradiance sun = sun_at_(origin + hit->t * node.toward, group.normal);
      if (sun.is_black()) continue;
      sum += node.weight * sun.spectrum() * static_cast<float>(cos_point);
    }
  });
  return Irradiance(sum);
}

}  // namespace skylit
