// The height field: a uniform grid of cells, each listing the triangles whose
// horizontal bounding box touches it; a query tests those triangles in barycentric
// coordinates of their horizontal projection.
#include "skylit/geometry/terrain_surface.h"

#include <algorithm>
#include <cmath>

namespace skylit {
namespace {

// Twice the signed area of the triangle's horizontal projection.
double plan_area2(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

}  // namespace

TerrainSurface::TerrainSurface(const TriangleMesh& terrain) : mesh_(terrain) {
  BoundingBox box;
  size_t kept = 0;
  for (const auto& t : mesh_.triangles) {
    if (plan_area2(mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]) == 0) continue;
    for (uint32_t v : t) box.add(mesh_.vertices[v]);
    ++kept;
  }
  if (kept == 0) return;
  // About one triangle per cell, at most 4096 cells a side.
  const double w = std::max(box.hi.x - box.lo.x, 1e-9), h = std::max(box.hi.y - box.lo.y, 1e-9);
  cell_ = std::max(std::sqrt(w * h / static_cast<double>(kept)), std::max(w, h) / 4096.0);
  x0_ = box.lo.x;
  y0_ = box.lo.y;
  nx_ = static_cast<int>(w / cell_) + 1;
  ny_ = static_cast<int>(h / cell_) + 1;
  const auto cells_of = [&](const std::array<uint32_t, 3>& t, auto&& visit) {
    BoundingBox b;
    for (uint32_t v : t) b.add(mesh_.vertices[v]);
    const int i0 = std::clamp(static_cast<int>((b.lo.x - x0_) / cell_), 0, nx_ - 1);
    const int i1 = std::clamp(static_cast<int>((b.hi.x - x0_) / cell_), 0, nx_ - 1);
    const int j0 = std::clamp(static_cast<int>((b.lo.y - y0_) / cell_), 0, ny_ - 1);
    const int j1 = std::clamp(static_cast<int>((b.hi.y - y0_) / cell_), 0, ny_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) visit(static_cast<size_t>(j) * static_cast<size_t>(nx_) + static_cast<size_t>(i));
  };
  cell_start_.assign(static_cast<size_t>(nx_) * static_cast<size_t>(ny_) + 1, 0);
  for (const auto& t : mesh_.triangles)
    if (plan_area2(mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]) != 0)
      cells_of(t, [&](size_t c) { ++cell_start_[c + 1]; });
  for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_triangles_.resize(cell_start_.back());
  std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (uint32_t k = 0; k < mesh_.triangles.size(); ++k) {
    const auto& t = mesh_.triangles[k];
    if (plan_area2(mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]) != 0)
      cells_of(t, [&](size_t c) { cell_triangles_[fill[c]++] = k; });
  }
}

std::optional<double> TerrainSurface::height_at(double x, double y) const {
  if (nx_ == 0) return std::nullopt;
  const double fi = (x - x0_) / cell_, fj = (y - y0_) / cell_;
  if (!(fi >= 0 && fj >= 0 && fi <= nx_ && fj <= ny_)) return std::nullopt;
  const size_t i = static_cast<size_t>(std::min(static_cast<int>(fi), nx_ - 1));
  const size_t j = static_cast<size_t>(std::min(static_cast<int>(fj), ny_ - 1));
  const size_t c = j * static_cast<size_t>(nx_) + i;
  std::optional<double> height;
  const Vec3 p{x, y, 0};
  for (uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
    const auto& t = mesh_.triangles[cell_triangles_[k]];
    const Vec3 &a = mesh_.vertices[t[0]], &b = mesh_.vertices[t[1]], &d = mesh_.vertices[t[2]];
    const double area = plan_area2(a, b, d);
    // Barycentric weights; a point on a shared edge belongs to both triangles (the
    // tolerance, relative to the triangle's size, keeps it from falling between).
    const double wa = plan_area2(p, b, d) / area, wb = plan_area2(a, p, d) / area, wd = plan_area2(a, b, p) / area;
    constexpr double kEdge = -1e-9;
    if (wa < kEdge || wb < kEdge || wd < kEdge) continue;
    const double z = wa * a.z + wb * b.z + wd * d.z;
    if (!height || z > *height) height = z;
  }
  return height;
}

std::optional<double> seating_shift_m(const TerrainSurface& terrain,
                                      const std::vector<std::vector<Vec3>>& ground_rings) {
  std::optional<double> highest_clearance;
  const auto compare = [&](const Vec3& p) {
    if (const auto t = terrain.height_at(p.x, p.y))
      highest_clearance = std::max(highest_clearance.value_or(p.z - *t), p.z - *t);
  };
  for (const auto& ring : ground_rings) {
    for (size_t k = 0; k < ring.size(); ++k) {
      const Vec3 &a = ring[k], &b = ring[(k + 1) % ring.size()];
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      const int steps = std::min(static_cast<int>(std::ceil(length / kGroundSampleSpacingM)), 100000);
      for (int s = 0; s < std::max(steps, 1); ++s) {
        const double f = static_cast<double>(s) / std::max(steps, 1);
        compare(a + f * (b - a));
      }
    }
  }
  if (!highest_clearance) return std::nullopt;
  return -*highest_clearance;
}

std::optional<double> seat_on_terrain(const TerrainSurface& terrain, TriangleMesh& building,
                                      const std::vector<bool>& is_ground) {
  std::vector<std::vector<Vec3>> ground;
  for (size_t k = 0; k < building.triangles.size() && k < is_ground.size(); ++k)
    if (is_ground[k]) {
      const auto& t = building.triangles[k];
      ground.push_back({building.vertices[t[0]], building.vertices[t[1]], building.vertices[t[2]]});
    }
  if (ground.empty() && !building.vertices.empty()) {
    // No ground surface (LoD1 blocks with an open bottom, as in Delft's 3D BAG extract):
    // its walls' bottom edges, those within 1 cm of its lowest point, are its footprint.
    // Until 2026-12-07 such a building was not set down at all, and nothing said so.
    double lowest = building.vertices.front().z;
    for (const Vec3& v : building.vertices) lowest = std::min(lowest, v.z);
    for (const auto& t : building.triangles)
      for (size_t e = 0; e < 3; ++e) {
        const Vec3 &a = building.vertices[t[e]], &b = building.vertices[t[(e + 1) % 3]];
        if (a.z < lowest + 0.01 && b.z < lowest + 0.01) ground.push_back({a, b});
      }
  }
  const auto shift = seating_shift_m(terrain, ground);
  if (shift)
    for (Vec3& v : building.vertices) v.z += *shift;
  return shift;
}

}  // namespace skylit
