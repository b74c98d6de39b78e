// Shadow volumes of triangles for a directional light, clipped against rays exactly
// (Crow 1977, "Shadow algorithms for computer graphics"; see shadow_volumes.h and
// docs/geometry.md). Crow counts the volume faces a ray crosses; here each volume is
// clipped on its own and the intervals are united, which needs no count at the ray's
// origin (a camera standing in shade) and gives the same set.
#include "skylit/geometry/shadow_volumes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace skylit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Shadow or sunlight shorter than this fraction of the scene's size is rounding, not
// geometry: where a ray passes through a vertex shared by several triangles, the
// neighbouring prisms' intervals are computed from different planes and can miss
// each other by a few ulps.
constexpr double kRelativeTolerance = 1e-9;
// The BVH's boxes are padded by this much more, so a box test rounded the other way
// can never drop a prism that the exact clip would keep.
constexpr double kRelativeBoxPadding = 1e-8;
constexpr size_t kLeafSize = 4;
constexpr size_t kMaxLeafSize = 16;
constexpr int kMaxDepth = 60;  // the query's stack has room for kMaxDepth + 2 entries
constexpr int kBins = 16;
// A point light's frusta are tested in groups of at most this many, each behind a cone.
constexpr size_t kFrustaPerGroup = 4;

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
double max_abs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

bool lexicographic_less(const Vec3& a, const Vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

// Inside: dot(normal, x) >= offset.
struct HalfSpace {
  Vec3 normal;
  double offset;
};

// The triangle swept along -to_sun: three sides, then the triangle's own plane (cap).
struct Prism {
  std::array<HalfSpace, 4> faces;
};

// A prism's footprint in light space (coordinates along u, v, perpendicular to the
// sun), its highest point along the sun direction w, and where its prism is.
struct Footprint {
  double lo[2], hi[2], centre[2];
  double h_max;
  uint32_t prism;
};

// A BVH node over footprints. Inner (count == 0): left child is the next node, right
// child is `index`. Leaf: prisms [index, index + count).
struct BvhNode {
  double lo[2], hi[2];
  double h_max;  // nothing in the node reaches higher along w
  uint32_t index;
  uint32_t count;
};

}  // namespace

struct ShadowVolumes::Data {
  Vec3 w, u, v;  // light frame: w toward the sun
  double scale = 1;  // largest coordinate magnitude of the casting triangles, >= 1 m
  std::vector<Prism> prisms;  // in BVH leaf order; for a point light, frusta in mesh order
  std::vector<BvhNode> nodes;  // empty for a point light
  bool point_light = false;
  // A point light's frusta in groups, each inside a cone from the light.
  struct Group {
    Vec3 axis;          // unit, from the light toward the group's bounding sphere
    double sin_half;    // of the cone's half-angle; ≥ 1: the light is inside the sphere
    uint32_t begin, end;  // frusta [begin, end)
  };
  std::vector<Group> groups;
  Vec3 light;
};

namespace {

// Whether every edge (vertices welded by position, so meshes that repeat a vertex per
// face count) is used exactly once in each direction: a closed surface wound
// consistently. Anything else is treated as open, which is always safe.
bool closed_and_oriented(const TriangleMesh& mesh) {
  const auto& vs = mesh.vertices;
  std::vector<uint32_t> order(vs.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return lexicographic_less(vs[a], vs[b]); });
  std::vector<uint64_t> weld(vs.size());
  uint64_t id = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    if (k > 0 && lexicographic_less(vs[order[k - 1]], vs[order[k]])) ++id;
    weld[order[k]] = id;
  }
  std::vector<uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const uint64_t a = weld[t[0]], b = weld[t[1]], c = weld[t[2]];
    if (a == b || b == c || c == a) return false;
    edges.push_back(a << 32 | b);
    edges.push_back(b << 32 | c);
    edges.push_back(c << 32 | a);
  }
  std::sort(edges.begin(), edges.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
  for (uint64_t e : edges)
    if (!std::binary_search(edges.begin(), edges.end(), (e << 32) | (e >> 32))) return false;
  return !edges.empty();
}

double signed_volume(const TriangleMesh& mesh) {
  const Vec3 p0 = mesh.vertices[mesh.triangles.front()[0]];
  double sum = 0;
  for (const auto& t : mesh.triangles)
    sum += dot(mesh.vertices[t[0]] - p0, cross(mesh.vertices[t[1]] - p0, mesh.vertices[t[2]] - p0));
  return sum / 6;
}

// Mesh `id`, checked: not null, finite, indices in range (std::invalid_argument).
const TriangleMesh& checked_mesh(const std::vector<const TriangleMesh*>& meshes, size_t id) {
  if (!meshes[id]) throw std::invalid_argument("ShadowVolumes: mesh " + std::to_string(id) + " is null");
  const TriangleMesh& mesh = *meshes[id];
  for (const Vec3& p : mesh.vertices)
    if (!finite(p)) throw std::invalid_argument("ShadowVolumes: mesh " + std::to_string(id) + " has a non-finite coordinate");
  for (const auto& t : mesh.triangles)
    for (uint32_t index : t)
      if (index >= mesh.vertices.size())
        throw std::invalid_argument("ShadowVolumes: mesh " + std::to_string(id) + " refers to vertex " +
                                    std::to_string(index) + " of " + std::to_string(mesh.vertices.size()));
  return mesh;
}

// Which triangles of a mesh cast. A closed surface: a ray from outside toward the light
// that meets it leaves it through a triangle facing the light (winding numbers: it
// must cross outward as often as inward), so those triangles alone cast the whole
// shadow. The volume's sign says which way "outward" is wound. Otherwise every
// triangle casts. +1: triangles whose normal faces the light; −1: away; 0: all.
int casting_side(const TriangleMesh& mesh) {
  if (!closed_and_oriented(mesh)) return 0;
  const double volume = signed_volume(mesh);
  return volume > 0 ? 1 : (volume < 0 ? -1 : 0);
}

// The prism below triangle (p, q, r) along -w, or false if it has no volume (the
// triangle is degenerate or edge-on to the sun).
bool make_prism(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& w, Prism& prism) {
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

// The frustum behind triangle (p, q, r) seen from a point light at `light`, or false if
// it has no volume (degenerate, or edge-on to the light). Same face order as a prism:
// three sides through the light and an edge, then the cap (the triangle's plane).
bool make_frustum(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& light, Prism& frustum) {
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

// Clips origin + t direction, t in [lo, hi], to the prism; true if something is left.
bool clip(const Prism& prism, const Vec3& origin, const Vec3& direction, double& lo, double& hi) {
  for (int i = 0; i < 4; ++i) {
    const HalfSpace& f = prism.faces[i];
    const double a = dot(f.normal, origin) - f.offset;
    const double b = dot(f.normal, direction);
    if (b > 0) {
      lo = std::max(lo, -a / b);
    } else if (b < 0) {
      hi = std::min(hi, -a / b);
      if (!(lo < hi)) return false;
    } else if (a < 0 || (i == 3 && a == 0)) {
      // Parallel to the face and outside. The sides are closed, so a ray lying in a
      // side shared by two prisms is in both; the cap is open, so a ray running
      // along a sunlit surface (a view ray grazing the ground) stays sunlit.
      return false;
    }
  }
  return lo < hi;
}

double half_perimeter(const double lo[2], const double hi[2]) { return (hi[0] - lo[0]) + (hi[1] - lo[1]); }

// Binned surface-area heuristic in 2-D: a random line meets a convex set with
// probability proportional to its perimeter (Cauchy-Crofton), so perimeter is the cost.
class BvhBuilder {
 public:
  BvhBuilder(std::vector<Footprint>& items, std::vector<BvhNode>& nodes) : items_(items), nodes_(nodes) {}

  void build(size_t begin, size_t end, int depth) {
    const size_t node = nodes_.size();
    nodes_.push_back({});
    BvhNode bounds{{kInf, kInf}, {-kInf, -kInf}, -kInf, 0, 0};
    double clo[2] = {kInf, kInf}, chi[2] = {-kInf, -kInf};
    for (size_t i = begin; i < end; ++i) {
      const Footprint& f = items_[i];
      for (int k = 0; k < 2; ++k) {
        bounds.lo[k] = std::min(bounds.lo[k], f.lo[k]);
        bounds.hi[k] = std::max(bounds.hi[k], f.hi[k]);
        clo[k] = std::min(clo[k], f.centre[k]);
        chi[k] = std::max(chi[k], f.centre[k]);
      }
      bounds.h_max = std::max(bounds.h_max, f.h_max);
    }
    const size_t count = end - begin;
    bounds.index = static_cast<uint32_t>(begin);
    bounds.count = static_cast<uint32_t>(count);
    if (count <= kLeafSize || depth >= kMaxDepth) {
      nodes_[node] = bounds;
      return;
    }

    int best_axis = -1, best_bin = 0;
    double best_cost = kInf;
    for (int axis = 0; axis < 2; ++axis) {
      const double extent = chi[axis] - clo[axis];
      if (!(extent > 0)) continue;
      struct Bin {
        double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
        size_t n = 0;
      } bins[kBins];
      for (size_t i = begin; i < end; ++i) {
        Bin& b = bins[bin_of(items_[i], axis, clo[axis], extent)];
        ++b.n;
        for (int k = 0; k < 2; ++k) {
          b.lo[k] = std::min(b.lo[k], items_[i].lo[k]);
          b.hi[k] = std::max(b.hi[k], items_[i].hi[k]);
        }
      }
      // Cost of splitting after bin s: right side swept first, then the left.
      double right_cost[kBins];
      Bin acc;
      for (int s = kBins - 1; s > 0; --s) {
        grow(acc, bins[s]);
        right_cost[s] = acc.n ? half_perimeter(acc.lo, acc.hi) * acc.n : kInf;
      }
      acc = Bin{};
      for (int s = 0; s < kBins - 1; ++s) {
        grow(acc, bins[s]);
        if (acc.n == 0) continue;
        const double cost = half_perimeter(acc.lo, acc.hi) * acc.n + right_cost[s + 1];
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bin = s;
        }
      }
    }
    const bool worth_it = best_cost < half_perimeter(bounds.lo, bounds.hi) * count;
    if (best_axis < 0 || (!worth_it && count <= kMaxLeafSize)) {
      nodes_[node] = bounds;
      return;
    }

    auto first = items_.begin() + static_cast<ptrdiff_t>(begin);
    auto last = items_.begin() + static_cast<ptrdiff_t>(end);
    const double extent = chi[best_axis] - clo[best_axis];
    auto middle = std::partition(
        first, last, [&](const Footprint& f) { return bin_of(f, best_axis, clo[best_axis], extent) <= best_bin; });
    if (middle == first || middle == last) {  // cannot happen with a finite best_cost; be safe
      middle = first + static_cast<ptrdiff_t>(count / 2);
      std::nth_element(first, middle, last, [&](const Footprint& a, const Footprint& b) {
        return a.centre[best_axis] < b.centre[best_axis];
      });
    }
    const size_t mid = static_cast<size_t>(middle - items_.begin());
    build(begin, mid, depth + 1);
    bounds.index = static_cast<uint32_t>(nodes_.size());
    bounds.count = 0;
    build(mid, end, depth + 1);
    nodes_[node] = bounds;
  }

 private:
  template <typename Bin>
  static void grow(Bin& acc, const Bin& b) {
    acc.n += b.n;
    for (int k = 0; k < 2; ++k) {
      acc.lo[k] = std::min(acc.lo[k], b.lo[k]);
      acc.hi[k] = std::max(acc.hi[k], b.hi[k]);
    }
  }
  static int bin_of(const Footprint& f, int axis, double lo, double extent) {
    const int b = static_cast<int>((f.centre[axis] - lo) / extent * kBins);
    return std::clamp(b, 0, kBins - 1);
  }

  std::vector<Footprint>& items_;
  std::vector<BvhNode>& nodes_;
};

}  // namespace

std::unique_ptr<const ShadowVolumes::Data> ShadowVolumes::build(const std::vector<const TriangleMesh*>& meshes,
                                                                const Vec3& to_sun) {
  if (!finite(to_sun) || !(length(to_sun) > 0))
    throw std::invalid_argument("ShadowVolumes: to_sun must be a finite, non-zero vector");
  auto data = std::make_unique<Data>();
  data->w = normalize(to_sun);
  const Vec3 helper = std::abs(data->w.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  data->u = normalize(cross(helper, data->w));
  data->v = cross(data->w, data->u);

  std::vector<Prism> prisms;
  std::vector<std::array<Vec3, 3>> corners;  // of each prism's triangle, for its footprint
  for (size_t id = 0; id < meshes.size(); ++id) {
    const TriangleMesh& mesh = checked_mesh(meshes, id);
    if (mesh.triangles.empty()) continue;
    const int keep = casting_side(mesh);
    for (const auto& t : mesh.triangles) {
      const Vec3 &p = mesh.vertices[t[0]], &q = mesh.vertices[t[1]], &r = mesh.vertices[t[2]];
      if (keep != 0 && !(keep * dot(cross(q - p, r - p), data->w) > 0)) continue;
      Prism prism;
      if (!make_prism(p, q, r, data->w, prism)) continue;
      prisms.push_back(prism);
      corners.push_back({p, q, r});
      data->scale = std::max({data->scale, max_abs(p), max_abs(q), max_abs(r)});
    }
  }
  if (prisms.size() > std::numeric_limits<uint32_t>::max())
    throw std::length_error("ShadowVolumes: more than 2^32-1 casting triangles");

  const double pad = kRelativeBoxPadding * data->scale;
  std::vector<Footprint> items(prisms.size());
  for (size_t i = 0; i < prisms.size(); ++i) {
    Footprint& f = items[i];
    f = {{kInf, kInf}, {-kInf, -kInf}, {0, 0}, -kInf, static_cast<uint32_t>(i)};
    for (const Vec3& c : corners[i]) {
      const double uv[2] = {dot(c, data->u), dot(c, data->v)};
      for (int k = 0; k < 2; ++k) {
        f.lo[k] = std::min(f.lo[k], uv[k] - pad);
        f.hi[k] = std::max(f.hi[k], uv[k] + pad);
      }
      f.h_max = std::max(f.h_max, dot(c, data->w) + pad);
    }
    for (int k = 0; k < 2; ++k) f.centre[k] = 0.5 * (f.lo[k] + f.hi[k]);
  }
  if (!items.empty()) {
    data->nodes.reserve(2 * items.size() / kLeafSize + 1);
    BvhBuilder(items, data->nodes).build(0, items.size(), 0);
  }
  data->prisms.reserve(prisms.size());
  for (const Footprint& f : items) data->prisms.push_back(prisms[f.prism]);
  return data;
}

namespace {

// The ray in light space: footprint position q0 + t dq, height h0 + t dh along w.
struct LightRay {
  double q0[2], dq[2], inv[2];
  double h0, dh;
};

// Whether the ray's footprint meets the node's box for some t in [t0, t1] at which
// the ray is not higher (toward the sun) than everything in the node.
bool may_meet(const BvhNode& node, const LightRay& r, double t0, double t1) {
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
  return !(lowest > node.h_max);
}

}  // namespace

ShadowVolumes::ShadowVolumes(const std::vector<TriangleMesh>& meshes, const Vec3& to_sun) {
  std::vector<const TriangleMesh*> pointers;
  pointers.reserve(meshes.size());
  for (const TriangleMesh& m : meshes) pointers.push_back(&m);
  data_ = build(pointers, to_sun);
}

ShadowVolumes::ShadowVolumes(const std::vector<const TriangleMesh*>& meshes, const Vec3& to_sun)
    : data_(build(meshes, to_sun)) {}

ShadowVolumes::ShadowVolumes(std::unique_ptr<const Data> data) : data_(std::move(data)) {}

ShadowVolumes ShadowVolumes::for_point_light(const std::vector<const TriangleMesh*>& meshes, const Vec3& light,
                                             const Vec3& aim, double max_gamma_deg) {
  return ShadowVolumes(build_point(meshes, light, aim, max_gamma_deg));
}

std::unique_ptr<const ShadowVolumes::Data> ShadowVolumes::build_point(const std::vector<const TriangleMesh*>& meshes,
                                                                      const Vec3& light, const Vec3& aim,
                                                                      double max_gamma_deg) {
  if (!finite(light)) throw std::invalid_argument("ShadowVolumes: the light's position must be finite");
  auto data = std::make_unique<Data>();
  data->point_light = true;
  data->w = {0, 0, 1};
  data->scale = std::max(1.0, max_abs(light));
  data->light = light;
  for (size_t id = 0; id < meshes.size(); ++id) {
    const TriangleMesh& mesh = checked_mesh(meshes, id);
    if (mesh.triangles.empty()) continue;
    // A closed surface is left through triangles facing the light, as for the sun.
    const int keep = casting_side(mesh);
    std::vector<Vec3> corners;  // of the group being filled
    auto close_group = [&] {
      const uint32_t begin = data->groups.empty() ? 0 : data->groups.back().end;
      const uint32_t end = static_cast<uint32_t>(data->prisms.size());
      if (end == begin) return;
      Vec3 centre{0, 0, 0};
      for (const Vec3& c : corners) centre += c;
      centre = centre / static_cast<double>(corners.size());
      double radius = 0;
      for (const Vec3& c : corners) radius = std::max(radius, length(c - centre));
      const double distance = length(centre - light);
      // Padded so that rounding never drops a frustum the exact clip would keep.
      radius = radius * (1 + 1e-9) + kRelativeBoxPadding * data->scale;
      data->groups.push_back({distance > radius ? (centre - light) / distance : Vec3{0, 0, 1},
                              distance > radius ? radius / distance : 2.0, begin, end});
      corners.clear();
    };
    for (const auto& t : mesh.triangles) {
      const Vec3 &p = mesh.vertices[t[0]], &q = mesh.vertices[t[1]], &r = mesh.vertices[t[2]];
      if (keep != 0 && !(keep * dot(cross(q - p, r - p), light - p) > 0)) continue;
      if (outside_cone(p, q, r, light, aim, max_gamma_deg)) continue;
      Prism frustum;
      if (!make_frustum(p, q, r, light, frustum)) continue;
      data->prisms.push_back(frustum);
      corners.insert(corners.end(), {p, q, r});
      data->scale = std::max({data->scale, max_abs(p), max_abs(q), max_abs(r)});
      if (corners.size() >= 3 * kFrustaPerGroup) close_group();
    }
    close_group();
  }
  return data;
}

ShadowVolumes::~ShadowVolumes() = default;
ShadowVolumes::ShadowVolumes(ShadowVolumes&&) noexcept = default;
ShadowVolumes& ShadowVolumes::operator=(ShadowVolumes&&) noexcept = default;

size_t ShadowVolumes::volume_count() const { return data_->prisms.size(); }
const Vec3& ShadowVolumes::to_sun() const { return data_->w; }

std::vector<Interval> ShadowVolumes::sunlit_intervals(const Ray& ray, double t_min, double t_max) const {
  std::vector<Interval> out;
  sunlit_intervals(ray, t_min, t_max, out);
  return out;
}

std::vector<Interval> ShadowVolumes::sunlit_intervals(const Ray& ray) const {
  return sunlit_intervals(ray, ray.t_min, ray.t_max);
}

double ShadowVolumes::sunlit_length(const Ray& ray, double t_min, double t_max) const {
  std::vector<Interval> lit;
  sunlit_intervals(ray, t_min, t_max, lit);
  double sum = 0;
  for (const Interval& i : lit) sum += i.end - i.begin;
  return sum;
}

namespace {

void collect_prism_shadows(const Vec3& u, const Vec3& v, const Vec3& w, const std::vector<BvhNode>& nodes,
                           const std::vector<Prism>& prisms, const Vec3& o, const Vec3& dir, double t_min, double t_max,
                           std::vector<Interval>& out) {
  LightRay r;
  r.q0[0] = dot(o, u);
  r.q0[1] = dot(o, v);
  r.dq[0] = dot(dir, u);
  r.dq[1] = dot(dir, v);
  for (int k = 0; k < 2; ++k) r.inv[k] = r.dq[k] != 0 ? 1 / r.dq[k] : 0;
  r.h0 = dot(o, w);
  r.dh = dot(dir, w);
  std::array<uint32_t, kMaxDepth + 2> stack;
  size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const BvhNode& node = nodes[index];
    if (!may_meet(node, r, t_min, t_max)) continue;
    if (node.count == 0) {
      stack[top++] = node.index;
      stack[top++] = index + 1;
      continue;
    }
    for (uint32_t i = node.index; i < node.index + node.count; ++i) {
      double lo = t_min, hi = t_max;
      if (clip(prisms[i], o, dir, lo, hi)) out.push_back({lo, hi});
    }
  }
}

// Turns the shadow intervals in `out` into the lit pieces of [t_min, t_max].
void unite_and_complement(double t_min, double t_max, double tolerance, std::vector<Interval>& out) {
  // Union of the shadow intervals; gaps within the tolerance are closed.
  std::sort(out.begin(), out.end(),
            [](const Interval& a, const Interval& b) { return a.begin < b.begin || (a.begin == b.begin && a.end < b.end); });
  size_t merged = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    if (merged > 0 && out[i].begin <= out[merged - 1].end + tolerance)
      out[merged - 1].end = std::max(out[merged - 1].end, out[i].end);
    else
      out[merged++] = out[i];
  }
  out.resize(merged);

  // Complement within [t_min, t_max], in place: the k-th sunlit piece is written
  // before the k-th shadow is overwritten, since each shadow adds at most one piece.
  size_t written = 0;
  double cursor = t_min;
  for (size_t i = 0; i < merged; ++i) {
    const Interval shadow = out[i];
    if (!(shadow.end - shadow.begin > tolerance)) continue;
    if (shadow.begin - cursor > tolerance) out[written++] = {cursor, shadow.begin};
    cursor = std::max(cursor, shadow.end);
  }
  out.resize(written);
  if (t_max - cursor > tolerance) out.push_back({cursor, t_max});
}

}  // namespace

void ShadowVolumes::sunlit_intervals(const Ray& ray, double t_min, double t_max, std::vector<Interval>& out) const {
  out.clear();
  if (std::isnan(t_min) || std::isnan(t_max) || t_min > t_max) return;
  const Data& d = *data_;
  const Vec3& o = ray.origin;
  const Vec3& dir = ray.direction;
  if (!finite(o) || !finite(dir) || (d.nodes.empty() && !d.point_light) || d.prisms.empty()) {
    if (t_max > t_min) out.push_back({t_min, t_max});
    return;
  }
  const double dir_length = length(dir);
  const double tolerance = dir_length > 0 ? kRelativeTolerance * std::max(d.scale, max_abs(o)) / dir_length : 0;

  // Shadow: every volume's interval, collected in `out` and then turned into light.
  if (d.point_light) {
    // The view ray and the light span a plane; a group's cone that the plane misses
    // (its axis further than the cone's half-angle from the plane) holds no frustum the
    // ray can meet.
    const Vec3 normal = cross(o - d.light, dir);
    const double normal_length = length(normal);
    for (const ShadowVolumes::Data::Group& g : d.groups) {
      if (g.sin_half < 1 && normal_length > 0 && std::abs(dot(g.axis, normal)) > g.sin_half * normal_length) continue;
      for (uint32_t i = g.begin; i < g.end; ++i) {
        double lo = t_min, hi = t_max;
        if (clip(d.prisms[i], o, dir, lo, hi)) out.push_back({lo, hi});
      }
    }
  } else {
    collect_prism_shadows(d.u, d.v, d.w, d.nodes, d.prisms, o, dir, t_min, t_max, out);
  }
  unite_and_complement(t_min, t_max, tolerance, out);
}

}  // namespace skylit
