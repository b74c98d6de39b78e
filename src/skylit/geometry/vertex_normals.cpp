#include "skylit/geometry/vertex_normals.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"
#include "skylit/core/huge_pages.h"

namespace skylit {
namespace {

Vec3 as_vec3(const std::array<float, 3>& n) { return {n[0], n[1], n[2]}; }

std::array<float, 3> as_floats(const Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

}  // namespace

std::vector<CornerNormals> crease_angle_normals(const TriangleMesh& mesh, double crease_angle_deg) {
  const size_t n = mesh.triangles.size();
  // The working arrays of a million-triangle model are 4–24 MB each: in 2 MiB pages
  // (core/huge_pages.h).
  HugePageVector<Vec3> unit(n);
  // Each corner's interior angle: the weight of its triangle's normal there.
  HugePageVector<std::array<double, 3>> angle(n);
  for (size_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 a = mesh.vertices[tri[0]];
    const Vec3 normal = cross(mesh.vertices[tri[1]] - a, mesh.vertices[tri[2]] - a);
    const double len = length(normal);
    unit[t] = len > 0 && std::isfinite(len) ? normal / len : Vec3{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      const Vec3 p = mesh.vertices[tri[c]];
      const Vec3 e1 = mesh.vertices[tri[(c + 1) % 3]] - p, e2 = mesh.vertices[tri[(c + 2) % 3]] - p;
      angle[t][c] = std::atan2(length(cross(e1, e2)), dot(e1, e2));
    }
  }
  // The corners at each position, in triangle order: vertices sorted by position give
  // each distinct position a number (two vertices at one place share it), and a counting
  // sort lists the corners by that number.
  HugePageVector<uint32_t> by_position(mesh.vertices.size());
  for (uint32_t v = 0; v < by_position.size(); ++v) by_position[v] = v;
  const auto key = [&](uint32_t v) {
    const Vec3& p = mesh.vertices[v];
    return std::array<double, 3>{p.x, p.y, p.z};
  };
  std::sort(by_position.begin(), by_position.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
  HugePageVector<uint32_t> place(mesh.vertices.size());
  uint32_t places = 0;
  for (size_t i = 0; i < by_position.size(); ++i) {
    if (i > 0 && key(by_position[i]) != key(by_position[i - 1])) ++places;
    place[by_position[i]] = places;
  }
  HugePageVector<uint32_t> run_start(static_cast<size_t>(places) + 2, 0);
  for (const auto& tri : mesh.triangles)
    for (uint32_t v : tri) ++run_start[place[v] + 1];
  for (size_t i = 1; i < run_start.size(); ++i) run_start[i] += run_start[i - 1];
  HugePageVector<std::pair<uint32_t, int>> corners(3 * n);
  {
    HugePageVector<uint32_t> fill(run_start.begin(), run_start.end() - 1);
    for (size_t t = 0; t < n; ++t)
      for (int c = 0; c < 3; ++c) corners[fill[place[mesh.triangles[t][c]]]++] = {static_cast<uint32_t>(t), c};
  }
  const double cos_crease = std::cos(radians(std::clamp(crease_angle_deg, 0.0, 180.0)));
  std::vector<CornerNormals> out(n);
  for (size_t run = 0; run + 1 < run_start.size(); ++run) {
    const size_t first = run_start[run], last = run_start[run + 1];
    for (size_t i = first; i < last; ++i) {
      const auto [t, c] = corners[i];
      // Normals weighted by the corner angles (G. Thürmer and C. A. Wüthrich, "Computing
      // vertex normals from polygonal facets", J. Graphics Tools 3(1), 1998): unlike
      // area weights, they do not depend on how a facet was cut into triangles.
      Vec3 sum{0, 0, 0};
      for (size_t j = first; j < last; ++j) {
        const auto [other, oc] = corners[j];
        if (other == t || dot(unit[t], unit[other]) >= cos_crease) sum += angle[other][oc] * unit[other];
      }
      const double len = length(sum);
      out[t][c] = as_floats(len > 0 && std::isfinite(len) ? sum / len : Vec3{0, 0, 1});
    }
  }
  return out;
}

void sanitize_file_normals(const TriangleMesh& mesh, std::vector<CornerNormals>& normals) {
  normals.resize(mesh.triangles.size(), CornerNormals{});
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 a = mesh.vertices[tri[0]];
    const Vec3 g = cross(mesh.vertices[tri[1]] - a, mesh.vertices[tri[2]] - a);
    const double g_len = length(g);
    const Vec3 flat = g_len > 0 && std::isfinite(g_len) ? g / g_len : Vec3{0, 0, 1};
    for (auto& corner : normals[t]) {
      const Vec3 n = as_vec3(corner);
      const double len = length(n);
      if (!(len > 1e-6 && std::isfinite(len)))
        corner = as_floats(flat);
      else
        corner = as_floats((dot(n, flat) < 0 ? -1.0 : 1.0) * n / len);
    }
  }
}

void transform_corner_normals(std::vector<CornerNormals>& normals, const Transform& transform) {
  const bool mirror = transform.determinant() < 0;
  for (CornerNormals& corners : normals) {
    for (auto& corner : corners) corner = as_floats(transform.apply_normal(as_vec3(corner)));
    if (mirror) std::swap(corners[1], corners[2]);
  }
}

bool any_smooth_corner(const TriangleMesh& mesh, const std::vector<CornerNormals>& normals, double tolerance_deg) {
  const double cos_tolerance = std::cos(radians(tolerance_deg));
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 g = cross(mesh.vertices[tri[1]] - mesh.vertices[tri[0]], mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
    const double len = length(g);
    if (!(len > 0)) continue;
    for (const auto& corner : normals[t])
      if (dot(normalize(as_vec3(corner)), g / len) < cos_tolerance) return true;  // float storage: renormalised
  }
  return false;
}

Vec3 shading_point(const std::array<Vec3, 3>& corners, const CornerNormals& normals, double b1, double b2) {
  const double b[3] = {1 - b1 - b2, b1, b2};
  const Vec3 p = b[0] * corners[0] + b[1] * corners[1] + b[2] * corners[2];
  Vec3 lifted{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const Vec3 n = as_vec3(normals[i]);
    const double below = std::min(0.0, dot(p - corners[i], n));
    lifted += b[i] * (p - below * n);
  }
  return lifted;
}

}  // namespace skylit
