// A hierarchy of boxes, each with a cone of directions, for ReflectedSun
// (render/reflected_sun.h): given a point, it visits the items whose box may lie within
// their cone as seen from the point, and passes over whole subtrees whose bounding box
// lies outside the cone that holds all their items' cones. A curved glossy model has an
// orientation class per triangle; testing them one by one cost each cache point tens of
// thousands of tests, where neighbouring triangles face alike and are passed over
// together.
#pragma once

#include <cstdint>
#include <vector>

#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// A box and the cone about `axis` (unit) of half-angle acos(cos_spread) holding the
// directions something in it sends or receives along.
struct BoxCone {
  BoundingBox box;
  Vec3 axis{0, 0, 1};
  double cos_spread = -1;
};

// Whether the box may lie within the cone from `origin`: the angle to the box's centre
// within the cone's half-angle plus the angle its bounding sphere subtends, by cosines.
// Conservative: a box that might meet the cone does. `pad_m` widens the box's sphere.
bool box_in_cone(const Vec3& origin, const BoxCone& cone, double pad_m);

class ConeTree {
 public:
  ConeTree() = default;
  // Items by index; the tree keeps its own copy of their boxes and cones.
  explicit ConeTree(const std::vector<BoxCone>& items, double pad_m);

  // Calls visit(index) for every item whose cone may meet its box from `origin`, in a
  // fixed order.
  template <typename Visit>
  void visit(const Vec3& origin, Visit&& visit) const {
    if (nodes_.empty()) return;
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<size_t>(stack[--top])];
      if (!box_in_cone(origin, node.cone, pad_m_)) continue;
      if (node.count > 0) {
        for (int32_t i = node.first; i < node.first + node.count; ++i) {
          const int32_t item = order_[static_cast<size_t>(i)];
          if (box_in_cone(origin, items_[static_cast<size_t>(item)], pad_m_)) visit(static_cast<size_t>(item));
        }
      } else {
        stack[top++] = node.second_child;
        stack[top++] = node.first;  // the first child is visited first
      }
    }
  }

 private:
  struct Node {
    BoxCone cone;       // bounds every item's box and cone below
    int32_t first = 0;  // a leaf: its first item in order_; else its first child's node
    int32_t count = 0;  // items of a leaf; 0 for an inner node
    int32_t second_child = 0;
  };
  int32_t build(int32_t first, int32_t count, int depth);

  std::vector<BoxCone> items_;
  std::vector<int32_t> order_;
  std::vector<Node> nodes_;
  double pad_m_ = 0;
};

}  // namespace skylit
