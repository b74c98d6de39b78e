#include "skylit/geometry/convex_faces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "skylit/geometry/shadow_casters.h"

namespace skylit {

namespace {

// Union-find over the triangles.
uint32_t root_of(std::vector<uint32_t>& parent, uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Twice the signed area of the 2-D triangle (o, a, b).
double cross2(const std::array<double, 2>& o, const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

}  // namespace

std::vector<ConvexFace> convex_faces(const TriangleMesh& mesh) {
  const size_t n = mesh.triangles.size();
  double scale = 1;
  for (const Vec3& v : mesh.vertices) scale = std::max(scale, max_abs(v));
  // Vertices equal in position get one id, so that separately written panels join.
  std::vector<uint32_t> order(mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0U);
  std::sort(order.begin(), order.end(),
            [&](uint32_t a, uint32_t b) { return lexicographic_less(mesh.vertices[a], mesh.vertices[b]); });
  std::vector<uint32_t> id(mesh.vertices.size());
  for (size_t k = 0; k < order.size(); ++k) {
    const bool same = k > 0 && !lexicographic_less(mesh.vertices[order[k - 1]], mesh.vertices[order[k]]);
    id[order[k]] = same ? id[order[k - 1]] : order[k];
  }
  // Unit normals and plane offsets; degenerate triangles get none and join nothing.
  std::vector<Vec3> normal(n);
  std::vector<double> offset(n);
  std::vector<bool> flat(n, true);
  for (size_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 &p = mesh.vertices[tri[0]], &q = mesh.vertices[tri[1]], &r = mesh.vertices[tri[2]];
    const Vec3 c = cross(q - p, r - p);
    const double area2 = length(c);
    if (!(area2 > 0)) continue;
    normal[t] = c / area2;
    offset[t] = dot(normal[t], p);
    flat[t] = false;
  }
  // Edges by their ends' ids; neighbours across an edge join when coplanar.
  std::vector<std::pair<uint64_t, uint32_t>> edges;
  edges.reserve(3 * n);
  for (size_t t = 0; t < n; ++t) {
    if (flat[t]) continue;
    for (int k = 0; k < 3; ++k) {
      uint64_t a = id[mesh.triangles[t][k]], b = id[mesh.triangles[t][(k + 1) % 3]];
      if (a > b) std::swap(a, b);
      edges.emplace_back(a << 32 | b, static_cast<uint32_t>(t));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0U);
  for (size_t k = 1; k < edges.size(); ++k) {
    if (edges[k].first != edges[k - 1].first) continue;
    const uint32_t s = edges[k - 1].second, t = edges[k].second;
    if (dot(normal[s], normal[t]) < 1 - 1e-12 || std::abs(offset[s] - offset[t]) > 1e-9 * scale) continue;
    parent[root_of(parent, s)] = root_of(parent, t);
  }
  std::vector<std::vector<uint32_t>> groups(n);
  for (uint32_t t = 0; t < n; ++t) groups[root_of(parent, t)].push_back(t);

  std::vector<ConvexFace> faces;
  auto single = [&](uint32_t t) {
    const auto& tri = mesh.triangles[t];
    faces.push_back({{mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]}, normal[t]});
  };
  std::vector<std::pair<std::array<double, 2>, Vec3>> points;
  std::vector<size_t> hull;
  for (const std::vector<uint32_t>& group : groups) {
    if (group.empty()) continue;
    if (group.size() == 1) {
      single(group[0]);
      continue;
    }
    // In-plane coordinates (u, v, normal right-handed), the group's area and its hull.
    const Vec3 nz = normal[group[0]];
    const Vec3 helper = std::abs(nz.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalize(cross(helper, nz)), v = cross(nz, u);
    points.clear();
    double area = 0;
    for (uint32_t t : group) {
      const auto& tri = mesh.triangles[t];
      const Vec3 &p = mesh.vertices[tri[0]], &q = mesh.vertices[tri[1]], &r = mesh.vertices[tri[2]];
      area += length(cross(q - p, r - p)) / 2;
      for (const Vec3* c : {&p, &q, &r}) points.push_back({{dot(*c, u), dot(*c, v)}, *c});
    }
    std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    // Andrew's monotone chain, counter-clockwise, points in line dropped.
    hull.assign(2 * points.size(), 0);
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      while (k >= 2 && cross2(points[hull[k - 2]].first, points[hull[k - 1]].first, points[i].first) <= 0) --k;
      hull[k++] = i;
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
      while (k >= lower && cross2(points[hull[k - 2]].first, points[hull[k - 1]].first, points[i].first) <= 0) --k;
      hull[k++] = i;
    }
    hull.resize(k - 1);  // the last repeats the first
    double hull_area = 0;
    for (size_t i = 1; i + 1 < hull.size(); ++i)
      hull_area += cross2(points[hull[0]].first, points[hull[i]].first, points[hull[i + 1]].first) / 2;
    if (hull.size() >= 3 && hull_area <= area * (1 + 1e-9)) {
      ConvexFace face{{}, nz};
      for (size_t i : hull) face.corners.push_back(points[i].second);
      faces.push_back(std::move(face));
    } else {
      for (uint32_t t : group) single(t);
    }
  }
  return faces;
}

}  // namespace skylit
