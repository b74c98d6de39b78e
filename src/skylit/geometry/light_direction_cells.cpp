// The cube map of a point light's directions (light_direction_cells.h).
#include "skylit/geometry/light_direction_cells.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skylit {

namespace {

// The cube's faces' pyramids widened by this much when faces are listed, so that a
// direction on the edge between two cube faces finds a face in both.
constexpr double kPyramidSlack = 1e-6;
// A face's projection widened by this much (of the face's [−1, 1]) when listed: the
// walk places a point in its cell to within rounding of the crossings it solves for.
constexpr double kProjectionSlack = 1e-8;

// The part of the polygon `in` (corners relative to the light) on the side of the plane
// through the light with normal m where dot(m, x) ≥ 0 (Sutherland–Hodgman).
std::vector<Vec3> clip_through_light(const std::vector<Vec3>& in, const Vec3& m) {
  std::vector<Vec3> out;
  const size_t n = in.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec3 &a = in[k], &b = in[(k + 1) % n];
    const double da = dot(m, a), db = dot(m, b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// x in single precision, rounded down (or up): a bound stays a bound.
float float_below(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float float_above(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

LightDirectionCells::CubeFace LightDirectionCells::cube_face(int f) {
  const int axis = f / 2;
  return {axis, (axis + 1) % 3, (axis + 2) % 3, f % 2 == 0 ? 1.0 : -1.0};
}

LightDirectionCells::LightDirectionCells(const Vec3& light, int cells_per_side)
    : light_(light),
      n_(cells_per_side),
      // A cell spans 2/n of the tangent plane at unit distance, widest (in angle) at a
      // face's centre: its half-diagonal there is √2/n, with a margin for rounding.
      cell_radius_rad_(1.01 * std::sqrt(2.0) / cells_per_side),
      cells_(static_cast<size_t>(6 * cells_per_side * cells_per_side)),
      gathering_top_z_(cells_.size(), -std::numeric_limits<double>::infinity()) {}

int LightDirectionCells::cell_index(double unit) const {
  const double f = (unit + 1.0) * 0.5 * n_;
  return f >= n_ ? n_ - 1 : (f > 0 ? static_cast<int>(f) : 0);
}

void LightDirectionCells::add(uint32_t item, const ConvexFace& face) {
  std::vector<Vec3> corners;
  double top_z = -std::numeric_limits<double>::infinity();
  for (const Vec3& c : face.corners) {
    corners.push_back(c - light_);
    top_z = std::max(top_z, c.z);
  }
  if (!(top_z < light_.z)) top_z = std::numeric_limits<double>::infinity();
  // The distance from the light to the face's plane.
  const double plane_m = std::abs(dot(face.normal, corners[0]));
  for (int f = 0; f < 6; ++f) {
    const CubeFace c = cube_face(f);
    std::vector<Vec3> part = corners;
    for (int k = 0; k < 4 && !part.empty(); ++k) {
      Vec3 m{0, 0, 0};
      m[c.axis] = c.sign * (1 + kPyramidSlack);
      m[k < 2 ? c.u_axis : c.v_axis] = (k & 1) ? 1.0 : -1.0;
      part = clip_through_light(part, m);
    }
    if (part.empty()) continue;
    double u_lo = 1, u_hi = -1, v_lo = 1, v_hi = -1;
    for (const Vec3& x : part) {
      const double along = c.sign * x[c.axis];
      // A corner of the clipped face at the light itself: its directions have no bound.
      if (!(along > 1e-12 * length(x))) {
        everywhere_.push_back(item);
        return;
      }
      const double u = x[c.u_axis] / along, v = x[c.v_axis] / along;
      u_lo = std::min(u_lo, u);
      u_hi = std::max(u_hi, u);
      v_lo = std::min(v_lo, v);
      v_hi = std::max(v_hi, v);
    }
    const int i0 = cell_index(u_lo - kProjectionSlack), i1 = cell_index(u_hi + kProjectionSlack);
    const int j0 = cell_index(v_lo - kProjectionSlack), j1 = cell_index(v_hi + kProjectionSlack);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const size_t index = static_cast<size_t>((f * n_ + j) * n_ + i);
        // In a direction w the face lies at plane_m / |n·w| at least; over the cell's
        // directions |n·w| is at most the cosine of the angle from its centre's to the
        // nearer of ±n less the cell's radius.
        Vec3 centre{0, 0, 0};
        centre[c.axis] = c.sign;
        centre[c.u_axis] = 2.0 * (i + 0.5) / n_ - 1.0;
        centre[c.v_axis] = 2.0 * (j + 0.5) / n_ - 1.0;
        const double cos_centre = std::min(1.0, std::abs(dot(face.normal, centre)) / length(centre));
        const double angle = std::max(0.0, std::acos(cos_centre) - cell_radius_rad_);
        const double nearest = plane_m / std::cos(angle) * (1 - 1e-9) - 1e-9 * length(corners[0]);
        gathering_.push_back({static_cast<uint32_t>(index), float_below(nearest), item});
        gathering_top_z_[index] = std::max(gathering_top_z_[index], top_z);
      }
  }
}

void LightDirectionCells::finish() {
  std::sort(gathering_.begin(), gathering_.end(), [](const Listed& a, const Listed& b) {
    return a.cell < b.cell || (a.cell == b.cell && a.nearest_m < b.nearest_m);
  });
  items_.reserve(gathering_.size());
  nearest_m_.reserve(gathering_.size());
  size_t next = 0;
  for (size_t k = 0; k < cells_.size(); ++k) {
    Cell& cell = cells_[k];
    cell.begin = static_cast<uint32_t>(items_.size());
    for (; next < gathering_.size() && gathering_[next].cell == k; ++next) {
      items_.push_back(gathering_[next].item);
      nearest_m_.push_back(gathering_[next].nearest_m);
    }
    cell.end = static_cast<uint32_t>(items_.size());
    cell.top_z = float_above(gathering_top_z_[k]);
  }
  gathering_ = {};
  gathering_top_z_ = {};
}

}  // namespace skylit
