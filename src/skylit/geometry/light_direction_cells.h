// The directions around a point light cut into the cells of a cube map, each listing
// the convex faces that may lie in its directions, with the least distance from the
// light at which they do and (for faces lit from above) how high they rise.
//
// A point light's shadow frusta (point_light_shadow_volumes.h) lie behind their faces:
// a point is in a face's frustum only if the face lies between it and the light, so in
// the point's direction from the light and nearer. A view ray's piece, walked cell by
// cell along the cube map, needs only the faces of the cells where it passes farther
// from the light than the cell's nearest face (and, lit from above, lower than its
// highest one). Bounds of this kind per direction are what a hierarchy of cones around
// faces' bounding spheres cannot give: from a lamp in a street a facade is seen at
// grazing angles, its sphere comes close to the lamp, and every piece of the street
// in front of the facade passed its test. docs/geometry.md, "Shadow volumes".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/convex_faces.h"

namespace skylit {

class LightDirectionCells {
 public:
  // A cell's faces are items [begin, end) of items(), nearest first: item k lies no
  // nearer to the light than nearest_m()[k] in the cell's directions, and none higher
  // than top_z (+∞ unless every one of them lies wholly below the light). The bounds
  // are in single precision, rounded outward.
  struct Cell {
    uint32_t begin = 0, end = 0;
    float top_z = 0;
  };

  // `cells_per_side` cells along each side of each of the cube's six faces.
  LightDirectionCells(const Vec3& light, int cells_per_side);

  // Lists `face` as item `item` in every cell its directions may fall in (the cells
  // its projection's bounding box meets, widened by far more than rounding), or in
  // every query's list when part of it lies at the light's own position.
  void add(uint32_t item, const ConvexFace& face);
  // Turns what add() gathered into the cells' lists; add() is not called after it.
  void finish();

  // Calls visit(cell, t_a, t_b) for each cell that o + t·dir passes through for t in
  // [t_min, t_max] (finite), with the part [t_a, t_b] of the piece in its directions,
  // in order along the piece. Cells with no items are skipped.
  template <typename Visit>
  void walk(const Vec3& o, const Vec3& dir, double t_min, double t_max, Visit&& visit) const;

  // Items to check on every query (faces through the light's own position).
  const std::vector<uint32_t>& everywhere() const { return everywhere_; }
  const std::vector<uint32_t>& items() const { return items_; }
  const std::vector<float>& nearest_m() const { return nearest_m_; }

 private:
  // One of the cube's faces: directions x with s·x[axis] ≥ |x[u_axis]|, |x[v_axis]|,
  // mapped to (x[u_axis], x[v_axis]) / (s·x[axis]) ∈ [−1, 1]².
  struct CubeFace {
    int axis, u_axis, v_axis;
    double sign;
  };
  static CubeFace cube_face(int f);
  int cell_index(double unit) const;  // the row or column of u ∈ [−1, 1]
  const Cell& cell(int f, int i, int j) const { return cells_[static_cast<size_t>((f * n_ + j) * n_ + i)]; }
  // The cells of cube face f along the piece's part in it.
  template <typename Visit>
  void walk_face(int f, const Vec3& p, const Vec3& dir, double lo, double hi, Visit& visit) const;

  Vec3 light_;
  int n_;
  double cell_radius_rad_;  // no cell's directions lie farther than this from its centre's
  std::vector<Cell> cells_;
  std::vector<uint32_t> items_, everywhere_;
  std::vector<float> nearest_m_;  // per item of items_
  struct Listed {
    uint32_t cell;
    float nearest_m;
    uint32_t item;
  };
  std::vector<Listed> gathering_;        // until finish()
  std::vector<double> gathering_top_z_;  // per cell, until finish()
};

template <typename Visit>
void LightDirectionCells::walk(const Vec3& o, const Vec3& dir, double t_min, double t_max, Visit&& visit) const {
  const Vec3 p = o - light_;
  // The piece's directions sweep one arc of a great circle, so each cube face holds
  // one interval of t: where the four planes bounding its pyramid all have the piece
  // on their inner side (each a linear condition on t). Walked in order along t.
  struct Part {
    double lo, hi;
    int face;
  };
  Part parts[6];
  int count = 0;
  for (int f = 0; f < 6; ++f) {
    const CubeFace c = cube_face(f);
    double lo = t_min, hi = t_max;
    bool empty = false;
    for (int k = 0; k < 4 && !empty; ++k) {
      const int other = k < 2 ? c.u_axis : c.v_axis;
      const double side = (k & 1) ? -1.0 : 1.0;
      const double a = c.sign * p[c.axis] - side * p[other], b = c.sign * dir[c.axis] - side * dir[other];
      if (b > 0)
        lo = std::max(lo, -a / b);
      else if (b < 0)
        hi = std::min(hi, -a / b);
      else if (a < 0)
        empty = true;
    }
    if (!empty && lo <= hi) parts[count++] = {lo, hi, f};
  }
  // In order of lo, by insertion: six at most (std::sort on this array drew GCC 12's
  // -Warray-bounds, a false alarm, into every build's log).
  for (int k = 1; k < count; ++k)
    for (int m = k; m > 0 && parts[m].lo < parts[m - 1].lo; --m) std::swap(parts[m], parts[m - 1]);
  for (int k = 0; k < count; ++k) walk_face(parts[k].face, p, dir, parts[k].lo, parts[k].hi, visit);
}

template <typename Visit>
void LightDirectionCells::walk_face(int f, const Vec3& p, const Vec3& dir, double lo, double hi, Visit& visit) const {
  const CubeFace c = cube_face(f);
  // u(t) = (p_u + t·d_u) / (s·(p_a + t·d_a)), monotonic where the denominator is
  // positive, as it is within the face's pyramid; so is v(t).
  const auto coordinate = [&](int other, double t) {
    const double along = c.sign * (p[c.axis] + t * dir[c.axis]);
    return along > 0 ? (p[other] + t * dir[other]) / along : 0.0;
  };
  // The cell of the interval's start (on a cell's edge, the one ahead if the piece moves
  // up in u or v, and if it moves down the first crossing below lies at the start).
  int i = cell_index(coordinate(c.u_axis, lo)), j = cell_index(coordinate(c.v_axis, lo));
  const int di = coordinate(c.u_axis, hi) >= coordinate(c.u_axis, lo) ? 1 : -1;
  const int dj = coordinate(c.v_axis, hi) >= coordinate(c.v_axis, lo) ? 1 : -1;
  // Where the piece crosses the cell's edge ahead along u (or v), u = edge:
  // p_u + t·d_u = edge·s·(p_a + t·d_a). The line's one solution is a crossing only
  // within the face's interval: u is monotonic there, so an edge ahead is crossed after
  // lo if at all. Its other solutions lie where s·x_a ≤ 0, outside [lo, hi]: before lo
  // they would read as a crossing behind (when u is constant, in a plane through the
  // light and a cube axis, every edge's solution is that point) and are never crossed.
  const auto crossing = [&](int other, int index, int step) {
    const double edge = 2.0 * (step > 0 ? index + 1 : index) / n_ - 1.0;
    const double num = edge * c.sign * p[c.axis] - p[other], den = dir[other] - edge * c.sign * dir[c.axis];
    const double t = num / den;
    return std::isfinite(t) && t >= lo && c.sign * (p[c.axis] + t * dir[c.axis]) > 0 ? t : hi;
  };
  double t = lo;
  double next_u = std::max(t, crossing(c.u_axis, i, di)), next_v = std::max(t, crossing(c.v_axis, j, dj));
  for (int steps = 0; steps <= 2 * n_ + 2; ++steps) {
    const double end = std::min({next_u, next_v, hi});
    const Cell& here = cell(f, i, j);
    if (here.end > here.begin) visit(here, t, end);
    if (end >= hi) return;
    t = end;
    // Past the face's last row or column the piece is on the next face but for
    // rounding: the rest of it stays in the edge's cell.
    if (next_u <= next_v) {
      i += di;
      next_u = i < 0 || i >= n_ ? hi : std::max(t, crossing(c.u_axis, i, di));
      i = std::clamp(i, 0, n_ - 1);
    } else {
      j += dj;
      next_v = j < 0 || j >= n_ ? hi : std::max(t, crossing(c.v_axis, j, dj));
      j = std::clamp(j, 0, n_ - 1);
    }
  }
}

}  // namespace skylit
