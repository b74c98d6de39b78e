// A bounding-volume hierarchy over boxes in a plane, each with a height bound along the
// plane's normal: the sun's shadow volumes are prisms along one direction, so a ray can
// meet only those whose footprints (in the plane perpendicular to the sun) its own
// footprint crosses, below their tops. Built with a binned surface-area heuristic in
// 2-D, where perimeter is the cost: a random line meets a convex set with probability
// proportional to its perimeter (Cauchy-Crofton).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace skylit {

// The hierarchy is at most this deep (deeper ranges become leaves), so a traversal's
// stack has a fixed size.
inline constexpr int kBvh2dMaxDepth = 60;

// An item's box [lo, hi] in the plane, its centre (where the builder bins it), the highest
// point of the item along the normal, and the caller's id for it.
struct Bvh2dItem {
  double lo[2], hi[2], centre[2];
  double top;
  uint32_t id;
};

// Inner node (count == 0): the left child is the next node, the right child is `index`.
// Leaf: items [index, index + count) in the builder's order.
struct Bvh2dNode {
  double lo[2], hi[2];
  double top;  // nothing in the node reaches higher
  uint32_t index;
  uint32_t count;
};

// Builds the hierarchy over `items`, which it reorders so that each leaf's items are
// contiguous (their ids say where each came from). Nothing for no items.
std::vector<Bvh2dNode> build_bvh_2d(std::vector<Bvh2dItem>& items);

// Calls leaf(begin, end) for the item range of every leaf reached through nodes that
// enter(node) accepts, depth first, left child first.
template <typename Enter, typename Leaf>
void traverse_bvh_2d(const std::vector<Bvh2dNode>& nodes, Enter&& enter, Leaf&& leaf) {
  if (nodes.empty()) return;
  std::array<uint32_t, kBvh2dMaxDepth + 2> stack;
  size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const Bvh2dNode& node = nodes[index];
    if (!enter(node)) continue;
    if (node.count == 0) {
      stack[top++] = node.index;
      stack[top++] = index + 1;
      continue;
    }
    leaf(node.index, node.index + node.count);
  }
}

}  // namespace skylit
