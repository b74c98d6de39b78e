// The sun's shadow volumes (sun_shadow_volumes.h): prisms along the sun's direction,
// found through a BVH over their footprints.
#include "skylit/geometry/sun_shadow_volumes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "skylit/geometry/shadow_casters.h"

namespace skylit {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The prism below triangle (p, q, r) along -w, or false if it has no volume (the
// triangle is degenerate or edge-on to the sun).
bool make_prism(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& w, ShadowVolume& prism) {
  const Vec3 n = cross(q - p, r - p);
  const double nw = dot(n, w);
  if (!(nw != 0)) return false;
  const double orientation = nw > 0 ? 1.0 : -1.0;
  const Vec3 corners[3] = {p, q, r};
  for (int i = 0; i < 3; ++i) {
    // The side through edge a -> b is the plane spanned by b - a and w; x is on the
    // triangle's side of it when -orientation * dot(cross(b - a, w), x - a) >= 0.
    // Two triangles sharing the edge must compute the same plane bit for bit, or a
    // ray crossing it could slip through a gap between their prisms; so the plane is
    // built from the edge's ends in one canonical order and only its sign differs.
    Vec3 a = corners[i], b = corners[(i + 1) % 3];
    double sign = -orientation;
    if (lexicographic_less(b, a)) {
      std::swap(a, b);
      sign = -sign;
    }
    const Vec3 m = cross(b - a, w);
    prism.faces[i] = {sign * m, sign * dot(m, a)};
  }
  // The cap: x is below the triangle's plane as seen from the sun.
  const Vec3 up = orientation * n;  // dot(up, w) > 0
  prism.faces[3] = {-up, -dot(up, p)};
  return true;
}

// The ray in light space: footprint position q0 + t dq, height h0 + t dh along w.
struct LightRay {
  double q0[2], dq[2], inv[2];
  double h0, dh;
};

// Whether the ray's footprint meets the node's box for some t in [t0, t1] at which
// the ray is not higher (toward the sun) than everything in the node.
bool may_meet(const Bvh2dNode& node, const LightRay& r, double t0, double t1) {
  for (int k = 0; k < 2; ++k) {
    if (r.dq[k] == 0) {
      if (r.q0[k] < node.lo[k] || r.q0[k] > node.hi[k]) return false;
    } else {
      double ta = (node.lo[k] - r.q0[k]) * r.inv[k], tb = (node.hi[k] - r.q0[k]) * r.inv[k];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
  }
  if (t0 > t1) return false;
  // A point above every triangle of the node (along w) is in none of their prisms.
  const double lowest = r.dh > 0 ? r.h0 + t0 * r.dh : (r.dh < 0 ? r.h0 + t1 * r.dh : r.h0);
  return !(lowest > node.top);
}

}  // namespace

SunShadowVolumes::SunShadowVolumes(const std::vector<TriangleMesh>& meshes, const Vec3& to_sun) {
  std::vector<const TriangleMesh*> pointers;
  pointers.reserve(meshes.size());
  for (const TriangleMesh& m : meshes) pointers.push_back(&m);
  build(pointers, to_sun);
}

SunShadowVolumes::SunShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& to_sun) {
  build(meshes, to_sun);
}

void SunShadowVolumes::build(const std::vector<const TriangleMesh*>& meshes, const Vec3& to_sun) {
  if (!is_finite(to_sun) || !(length(to_sun) > 0))
    throw std::invalid_argument("SunShadowVolumes: to_sun must be a finite, non-zero vector");
  w_ = normalize(to_sun);
  const Vec3 helper = std::abs(w_.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  u_ = normalize(cross(helper, w_));
  v_ = cross(w_, u_);

  std::vector<ShadowVolume> prisms;
  std::vector<std::array<Vec3, 3>> corners;  // of each prism's triangle, for its footprint
  for (size_t id = 0; id < meshes.size(); ++id) {
    const TriangleMesh& mesh = checked_mesh(meshes, id, "SunShadowVolumes");
    if (mesh.triangles.empty()) continue;
    const int keep = casting_side(mesh);
    for (const auto& t : mesh.triangles) {
      const Vec3 &p = mesh.vertices[t[0]], &q = mesh.vertices[t[1]], &r = mesh.vertices[t[2]];
      if (keep != 0 && !(keep * dot(cross(q - p, r - p), w_) > 0)) continue;
      ShadowVolume prism;
      if (!make_prism(p, q, r, w_, prism)) continue;
      prisms.push_back(prism);
      corners.push_back({p, q, r});
      scale_ = std::max({scale_, max_abs(p), max_abs(q), max_abs(r)});
    }
  }
  if (prisms.size() > std::numeric_limits<uint32_t>::max())
    throw std::length_error("SunShadowVolumes: more than 2^32-1 casting triangles");

  // Footprints in (u, v) and tops along w, padded so that the BVH's box tests never
  // drop a prism the exact clip would keep.
  const double pad = kRelativeShadowBoundPadding * scale_;
  std::vector<Bvh2dItem> items(prisms.size());
  for (size_t i = 0; i < prisms.size(); ++i) {
    Bvh2dItem& f = items[i];
    f = {{kInf, kInf}, {-kInf, -kInf}, {0, 0}, -kInf, static_cast<uint32_t>(i)};
    for (const Vec3& c : corners[i]) {
      const double uv[2] = {dot(c, u_), dot(c, v_)};
      for (int k = 0; k < 2; ++k) {
        f.lo[k] = std::min(f.lo[k], uv[k] - pad);
        f.hi[k] = std::max(f.hi[k], uv[k] + pad);
      }
      f.top = std::max(f.top, dot(c, w_) + pad);
    }
    for (int k = 0; k < 2; ++k) f.centre[k] = 0.5 * (f.lo[k] + f.hi[k]);
  }
  nodes_ = build_bvh_2d(items);
  prisms_.reserve(prisms.size());
  for (const Bvh2dItem& f : items) prisms_.push_back(prisms[f.id]);
}

std::vector<Interval> SunShadowVolumes::sunlit_intervals(const Ray& ray, double t_min, double t_max) const {
  std::vector<Interval> out;
  sunlit_intervals(ray, t_min, t_max, out);
  return out;
}

std::vector<Interval> SunShadowVolumes::sunlit_intervals(const Ray& ray) const {
  return sunlit_intervals(ray, ray.t_min, ray.t_max);
}

double SunShadowVolumes::sunlit_length(const Ray& ray, double t_min, double t_max) const {
  std::vector<Interval> lit;
  sunlit_intervals(ray, t_min, t_max, lit);
  return total_length(lit);
}

void SunShadowVolumes::sunlit_intervals(const Ray& ray, double t_min, double t_max, std::vector<Interval>& out) const {
  auto collect_shadows = [&](const Vec3& o, const Vec3& dir, std::vector<Interval>& shadows) {
    LightRay r;
    r.q0[0] = dot(o, u_);
    r.q0[1] = dot(o, v_);
    r.dq[0] = dot(dir, u_);
    r.dq[1] = dot(dir, v_);
    for (int k = 0; k < 2; ++k) r.inv[k] = r.dq[k] != 0 ? 1 / r.dq[k] : 0;
    r.h0 = dot(o, w_);
    r.dh = dot(dir, w_);
    traverse_bvh_2d(
        nodes_, [&](const Bvh2dNode& node) { return may_meet(node, r, t_min, t_max); },
        [&](uint32_t begin, uint32_t end) {
          for (uint32_t i = begin; i < end; ++i) {
            double lo = t_min, hi = t_max;
            if (clip_to_volume(prisms_[i], o, dir, lo, hi)) shadows.push_back({lo, hi});
          }
        });
  };
  lit_intervals_from_shadows(ray, t_min, t_max, scale_, nodes_.empty() || prisms_.empty(), collect_shadows, out);
}

}  // namespace skylit
