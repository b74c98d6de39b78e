#include "skylit/clouds/cloud_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skylit {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

CloudGrid::CloudGrid(const std::vector<Cloud>& clouds) {
  double x_lo = kInf, x_hi = -kInf, y_lo = kInf, y_hi = -kInf;
  z_lo_ = kInf;
  z_hi_ = -kInf;
  std::size_t count = 0;
  for (const Cloud& c : clouds) {
    if (c.empty()) continue;
    const CloudShape& s = c.shape();
    x_lo = std::min(x_lo, s.center_x - c.extent_x());
    x_hi = std::max(x_hi, s.center_x + c.extent_x());
    y_lo = std::min(y_lo, s.center_y - c.extent_y());
    y_hi = std::max(y_hi, s.center_y + c.extent_y());
    z_lo_ = std::min(z_lo_, s.altitude - 0.5 * s.max_thickness);
    z_hi_ = std::max(z_hi_, s.altitude + 0.5 * s.max_thickness);
    ++count;
  }
  if (count == 0) return;  // nx_ = 0: no candidates ever
  const double width = std::max(x_hi - x_lo, y_hi - y_lo);
  const int per_axis =
      std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)))), 1, kMaxCellsPerAxis);
  cell_ = std::max(width / per_axis, 1e-3);
  x0_ = x_lo;
  y0_ = y_lo;
  nx_ = std::clamp(static_cast<int>(std::ceil((x_hi - x_lo) / cell_)), 1, kMaxCellsPerAxis);
  ny_ = std::clamp(static_cast<int>(std::ceil((y_hi - y_lo) / cell_)), 1, kMaxCellsPerAxis);

  // Each footprint goes into every cell its box overlaps, widened by a sliver of a cell
  // so that a ray passing exactly through a cell corner (where the walk may step
  // diagonally past a cell) still finds it in a neighbour.
  const double pad = 1e-6 * cell_;
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  auto for_cells = [&](const Cloud& c, auto&& visit) {
    const CloudShape& s = c.shape();
    const int i0 = cell_x(s.center_x - c.extent_x() - pad), i1 = cell_x(s.center_x + c.extent_x() + pad);
    const int j0 = cell_y(s.center_y - c.extent_y() - pad), j1 = cell_y(s.center_y + c.extent_y() + pad);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) visit(static_cast<std::size_t>(j) * nx_ + i);
  };
  for (const Cloud& c : clouds)
    if (!c.empty()) for_cells(c, [&](std::size_t cell) { ++counts[cell + 1]; });
  for (std::size_t k = 1; k < counts.size(); ++k) counts[k] += counts[k - 1];
  first_ = counts;
  cloud_index_.resize(first_.back());
  for (std::size_t index = 0; index < clouds.size(); ++index)
    if (!clouds[index].empty())
      for_cells(clouds[index],
                [&](std::size_t cell) { cloud_index_[counts[cell]++] = static_cast<std::uint32_t>(index); });
}

int CloudGrid::cell_x(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 1);
}
int CloudGrid::cell_y(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 1);
}

void CloudGrid::candidates(const Vec3& o, const Vec3& d, double t_min, double t_max,
                           std::vector<std::uint32_t>& out) const {
  out.clear();
  if (nx_ == 0 || !(t_max > t_min)) return;
  // The part of the ray inside the clouds' slab and the grid's box.
  double lo = t_min, hi = t_max;
  auto clip_axis = [&](double origin, double direction, double a, double b) {
    if (direction == 0) {
      if (origin < a || origin > b) hi = -kInf;
      return;
    }
    double ta = (a - origin) / direction, tb = (b - origin) / direction;
    if (ta > tb) std::swap(ta, tb);
    lo = std::max(lo, ta);
    hi = std::min(hi, tb);
  };
  clip_axis(o.z, d.z, z_lo_, z_hi_);
  clip_axis(o.x, d.x, x0_, x0_ + nx_ * cell_);
  clip_axis(o.y, d.y, y0_, y0_ + ny_ * cell_);
  if (!(hi >= lo) || !std::isfinite(lo)) return;
  if (!std::isfinite(hi)) hi = lo;  // a vertical ray: the one cell where it starts

  // The walk (Amanatides and Woo): t at the next vertical and horizontal cell boundary.
  int i = cell_x(o.x + d.x * lo), j = cell_y(o.y + d.y * lo);
  const int i_end = cell_x(o.x + d.x * hi), j_end = cell_y(o.y + d.y * hi);
  const int step_i = d.x > 0 ? 1 : -1, step_j = d.y > 0 ? 1 : -1;
  const double dt_x = d.x != 0 ? cell_ / std::abs(d.x) : kInf, dt_y = d.y != 0 ? cell_ / std::abs(d.y) : kInf;
  double next_x = d.x != 0 ? (x0_ + (i + (d.x > 0 ? 1 : 0)) * cell_ - o.x) / d.x : kInf;
  double next_y = d.y != 0 ? (y0_ + (j + (d.y > 0 ? 1 : 0)) * cell_ - o.y) / d.y : kInf;
  // At most one cell per boundary crossed, plus the first: the walk cannot run away.
  for (int guard = nx_ + ny_ + 2; guard > 0; --guard) {
    const std::size_t cell = static_cast<std::size_t>(j) * nx_ + i;
    out.insert(out.end(), cloud_index_.begin() + first_[cell], cloud_index_.begin() + first_[cell + 1]);
    if (i == i_end && j == j_end) break;
    if (next_x < next_y) {
      if (next_x > hi) break;
      i += step_i;
      next_x += dt_x;
    } else {
      if (next_y > hi) break;
      j += step_j;
      next_y += dt_y;
    }
    if (i < 0 || i >= nx_ || j < 0 || j >= ny_) break;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace skylit
