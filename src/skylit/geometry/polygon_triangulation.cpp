// Ear clipping with hole bridges (see polygon_triangulation.h). The rings live in
// one circular doubly linked list of nodes; holes are spliced into the outer ring by
// a pair of coincident bridge edges, so the rest of the work sees one ring.
#include "skylit/geometry/polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skylit {
namespace {

struct Node {
  uint32_t index;  // into the polygon's points (outer ring, then holes)
  double x, y;
  uint32_t prev, next;
};

double signed_area(const std::vector<Point2>& ring) {
  double twice = 0;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    twice += (ring[j].x - ring[i].x) * (ring[j].y + ring[i].y);
  return 0.5 * twice;
}

// Twice the signed area of triangle (a, b, c): > 0 when it turns counter-clockwise.
double turn(const Node& a, const Node& b, const Node& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool same_place(const Node& a, const Node& b) { return a.x == b.x && a.y == b.y; }

// p inside or on the counter-clockwise triangle (a, b, c).
bool in_triangle(const Node& a, const Node& b, const Node& c, const Node& p) {
  return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

class EarClipper {
 public:
  explicit EarClipper(const Polygon2& polygon) {
    const double outer_area = signed_area(polygon.outer);
    if (polygon.outer.size() < 3 || !(outer_area != 0) || !std::isfinite(outer_area)) return;
    outer_clockwise_ = outer_area < 0;
    uint32_t first_index = 0;
    start_ = add_ring(polygon.outer, first_index, /*counter_clockwise=*/true);
    first_index += static_cast<uint32_t>(polygon.outer.size());

    // Holes from the one reaching furthest east to the west, so that each bridge
    // runs east to a ring that already holds every hole east of it.
    std::vector<uint32_t> rightmost;
    for (const auto& hole : polygon.holes) {
      if (hole.size() >= 3 && signed_area(hole) != 0) {
        const uint32_t first = add_ring(hole, first_index, /*counter_clockwise=*/false);
        rightmost.push_back(rightmost_node(first));
      }
      first_index += static_cast<uint32_t>(hole.size());
    }
    std::sort(rightmost.begin(), rightmost.end(), [&](uint32_t a, uint32_t b) {
      return nodes_[a].x != nodes_[b].x ? nodes_[a].x > nodes_[b].x : nodes_[a].y < nodes_[b].y;
    });
    for (uint32_t m : rightmost) bridge_hole(m);
  }

  std::vector<TriangleIndices> triangulate() {
    std::vector<TriangleIndices> triangles;
    if (nodes_.empty()) return triangles;
    size_t remaining = ring_size(start_);
    uint32_t current = start_;
    // How hard to look: 0 true ears only; 1 also drop vertices that add no area;
    // 2 cut any convex corner; 3 cut whatever corner (a broken input must end).
    int effort = 0;
    size_t tried = 0;
    while (remaining > 3) {
      const Node& node = nodes_[current];
      const uint32_t prev = node.prev, next = node.next;
      const double area = turn(nodes_[prev], node, nodes_[next]);
      bool cut = false, drop = false;
      if (effort == 0)
        cut = area > 0 && is_ear(current);
      else if (effort == 1)
        drop = area == 0;
      else if (effort == 2)
        cut = area > 0;
      else
        cut = true;
      if (cut || drop) {
        if (cut && area > 0) triangles.push_back(oriented(prev, current, next));
        unlink(current);
        --remaining;
        current = next;
        tried = 0;
        effort = 0;
        continue;
      }
      current = next;
      if (++tried >= remaining) {
        tried = 0;
        ++effort;
      }
    }
    const Node& last = nodes_[current];
    if (turn(nodes_[last.prev], last, nodes_[last.next]) > 0)
      triangles.push_back(oriented(last.prev, current, last.next));
    return triangles;
  }

 private:
  uint32_t add_ring(const std::vector<Point2>& ring, uint32_t first_index, bool counter_clockwise) {
    const bool reverse = (signed_area(ring) > 0) != counter_clockwise;
    const auto first = static_cast<uint32_t>(nodes_.size());
    const auto n = static_cast<uint32_t>(ring.size());
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t i = reverse ? n - 1 - k : k;
      nodes_.push_back({first_index + i, ring[i].x, ring[i].y, first + (k + n - 1) % n, first + (k + 1) % n});
    }
    return first;
  }

  uint32_t rightmost_node(uint32_t first) const {
    uint32_t best = first;
    for (uint32_t i = nodes_[first].next; i != first; i = nodes_[i].next)
      if (nodes_[i].x > nodes_[best].x || (nodes_[i].x == nodes_[best].x && nodes_[i].y < nodes_[best].y)) best = i;
    return best;
  }

  size_t ring_size(uint32_t first) const {
    size_t n = 1;
    for (uint32_t i = nodes_[first].next; i != first; i = nodes_[i].next) ++n;
    return n;
  }

  // Whether m lies inside the polygon's angle at corner a (between a's edges).
  bool locally_inside(uint32_t a, const Node& m) const {
    const Node& p = nodes_[nodes_[a].prev];
    const Node& q = nodes_[nodes_[a].next];
    const Node& c = nodes_[a];
    if (turn(p, c, q) >= 0)  // convex corner: m left of both edges
      return turn(c, q, m) >= 0 && turn(p, c, m) >= 0;
    return turn(c, q, m) >= 0 || turn(p, c, m) >= 0;  // reflex corner
  }

  // Joins the hole whose easternmost node is m to the outer ring (Eberly §3): the
  // ray from m toward +x meets the ring first on an edge; its eastern end, or a
  // reflex vertex in the triangle it spans with m and the meeting point, sees m.
  void bridge_hole(uint32_t m) {
    const Node mp = nodes_[m];
    double hit_x = std::numeric_limits<double>::infinity();
    uint32_t seen = std::numeric_limits<uint32_t>::max();
    uint32_t i = start_;
    do {
      const Node& a = nodes_[i];
      const Node& b = nodes_[a.next];
      // Edges with the inside to their west run north (the ring turns counter-clockwise).
      if (a.y <= mp.y && mp.y <= b.y && a.y < b.y) {
        const double x = a.x + (mp.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x >= mp.x && x < hit_x) {
          hit_x = x;
          seen = x == a.x ? i : x == b.x ? a.next : (a.x > b.x ? i : a.next);
        }
      }
      i = a.next;
    } while (i != start_);
    if (seen == std::numeric_limits<uint32_t>::max()) return;  // the hole is not inside: ignore it

    // Reflex vertices inside triangle (m, hit, seen) hide `seen`; the one closest in
    // angle to the ray is visible.
    if (hit_x != nodes_[seen].x || mp.y != nodes_[seen].y) {
      const Node hit{0, hit_x, mp.y, 0, 0};
      const Node s = nodes_[seen];
      const bool below = s.y < mp.y;
      const Node& t_a = mp;  // the triangle in counter-clockwise order
      const Node& t_b = below ? s : hit;
      const Node& t_c = below ? hit : s;
      double best_tan = std::numeric_limits<double>::infinity();
      double best_x = s.x;
      i = start_;
      do {
        const Node& p = nodes_[i];
        if (i != seen && p.x >= mp.x && p.x <= s.x && !same_place(p, mp) && in_triangle(t_a, t_b, t_c, p) &&
            locally_inside(i, mp)) {
          const double tan = std::abs(mp.y - p.y) / (p.x - mp.x);
          if (p.x > mp.x && (tan < best_tan || (tan == best_tan && p.x < best_x))) {
            best_tan = tan;
            best_x = p.x;
            seen = i;
          }
        }
        i = nodes_[i].next;
      } while (i != start_);
    }
    // A point where earlier bridges meet appears more than once: take the copy whose
    // corner m lies in.
    if (!locally_inside(seen, mp)) {
      i = start_;
      do {
        if (i != seen && same_place(nodes_[i], nodes_[seen]) && locally_inside(i, mp)) {
          seen = i;
          break;
        }
        i = nodes_[i].next;
      } while (i != start_);
    }
    split(seen, m);
  }

  // Adds the bridge a → b and its return b' → a' (copies of b and a).
  void split(uint32_t a, uint32_t b) {
    const auto a2 = static_cast<uint32_t>(nodes_.size());
    const uint32_t b2 = a2 + 1;
    const uint32_t an = nodes_[a].next, bp = nodes_[b].prev;
    nodes_.push_back(nodes_[a]);
    nodes_.push_back(nodes_[b]);
    nodes_[a].next = b;
    nodes_[b].prev = a;
    nodes_[a2].next = an;
    nodes_[an].prev = a2;
    nodes_[b2].next = a2;
    nodes_[a2].prev = b2;
    nodes_[bp].next = b2;
    nodes_[b2].prev = bp;
  }

  // The corner at `ear` can be cut off: no vertex of the ring that is not convex lies
  // in its triangle (if any vertex does, a reflex one does).
  bool is_ear(uint32_t ear) const {
    const Node& a = nodes_[nodes_[ear].prev];
    const Node& b = nodes_[ear];
    const Node& c = nodes_[b.next];
    for (uint32_t i = c.next; i != b.prev; i = nodes_[i].next) {
      const Node& p = nodes_[i];
      if (same_place(p, a) || same_place(p, b) || same_place(p, c)) continue;
      if (turn(nodes_[p.prev], p, nodes_[p.next]) <= 0 && in_triangle(a, b, c, p)) return false;
    }
    return true;
  }

  void unlink(uint32_t i) {
    nodes_[nodes_[i].prev].next = nodes_[i].next;
    nodes_[nodes_[i].next].prev = nodes_[i].prev;
    if (start_ == i) start_ = nodes_[i].next;
  }

  TriangleIndices oriented(uint32_t a, uint32_t b, uint32_t c) const {
    if (outer_clockwise_) return {nodes_[c].index, nodes_[b].index, nodes_[a].index};
    return {nodes_[a].index, nodes_[b].index, nodes_[c].index};
  }

  std::vector<Node> nodes_;
  uint32_t start_ = 0;
  bool outer_clockwise_ = false;
};

}  // namespace

std::vector<TriangleIndices> triangulate_polygon(const Polygon2& polygon) { return EarClipper(polygon).triangulate(); }

Vec3 newell_normal(const std::vector<Vec3>& ring) {
  Vec3 n{0, 0, 0};
  if (ring.empty()) return n;
  const Vec3 o = ring[0];  // relative to one point: survey coordinates keep their digits
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec3 a = ring[i] - o, b = ring[(i + 1) % ring.size()] - o;
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

std::vector<TriangleIndices> triangulate_polygon_3d(const std::vector<std::vector<Vec3>>& rings) {
  if (rings.empty() || rings[0].size() < 3) return {};
  const Vec3 n = newell_normal(rings[0]);
  const double len = length(n);
  if (!(len > 0) || !std::isfinite(len)) return {};
  const Vec3 w = n / len;
  // u, v, w right-handed, so the outer ring turns counter-clockwise in (u, v).
  const Vec3 u = normalize(std::abs(w.x) < 0.9 ? cross(Vec3{1, 0, 0}, w) : cross(Vec3{0, 1, 0}, w));
  const Vec3 v = cross(w, u);
  const Vec3 o = rings[0][0];
  const auto flat = [&](const std::vector<Vec3>& ring) {
    std::vector<Point2> out;
    out.reserve(ring.size());
    for (const Vec3& p : ring) out.push_back({dot(p - o, u), dot(p - o, v)});
    return out;
  };
  Polygon2 polygon;
  polygon.outer = flat(rings[0]);
  for (size_t r = 1; r < rings.size(); ++r) polygon.holes.push_back(flat(rings[r]));
  return triangulate_polygon(polygon);
}

}  // namespace skylit
