// Shadow-casting meshes (shadow_casters.h): input checks and the closed-surface test.
#include "skylit/geometry/shadow_casters.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>

namespace skylit {

bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
double max_abs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

bool lexicographic_less(const Vec3& a, const Vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

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

}  // namespace

const TriangleMesh& checked_mesh(const std::vector<const TriangleMesh*>& meshes, size_t id, const char* who) {
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument(std::string(who) + ": mesh " + std::to_string(id) + what);
  };
  if (!meshes[id]) fail(" is null");
  const TriangleMesh& mesh = *meshes[id];
  for (const Vec3& p : mesh.vertices)
    if (!is_finite(p)) fail(" has a non-finite coordinate");
  for (const auto& t : mesh.triangles)
    for (uint32_t index : t)
      if (index >= mesh.vertices.size())
        fail(" refers to vertex " + std::to_string(index) + " of " + std::to_string(mesh.vertices.size()));
  return mesh;
}

int casting_side(const TriangleMesh& mesh) {
  if (!closed_and_oriented(mesh)) return 0;
  const double volume = signed_volume(mesh);
  return volume > 0 ? 1 : (volume < 0 ? -1 : 0);
}

}  // namespace skylit
