// ConeTree (cone_tree.h).
#include "skylit/render/cone_tree.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

constexpr int kLeafItems = 4;
constexpr int kMaxDepth = 40;  // within the visit's stack of 64

// The angle between two unit vectors, robust near 0 and π.
double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

}  // namespace

bool box_in_cone(const Vec3& origin, const BoxCone& cone, double pad_m) {
  // Both angles below are under 90° where it matters (a wider cone passes at once), so
  // their sum is under 180°, where the cosine falls monotonically; acos and asin per test
  // took a fifth of a curved model's render.
  if (cone.cos_spread <= 0) return true;
  const Vec3 to_centre = cone.box.center() - origin;
  const double d = length(to_centre), radius = 0.5 * length(cone.box.size()) + pad_m;
  if (d <= radius) return true;
  const double sin_b = radius / d, cos_b = std::sqrt(1 - sin_b * sin_b);
  const double sin_spread = std::sqrt(std::max(0.0, 1 - cone.cos_spread * cone.cos_spread));
  const double cos_limit = cone.cos_spread * cos_b - sin_spread * sin_b;  // cos(spread + β)
  return dot(to_centre, cone.axis) >= (cos_limit - 1e-12) * d;
}

ConeTree::ConeTree(const std::vector<BoxCone>& items, double pad_m) : items_(items), pad_m_(pad_m) {
  if (items_.empty()) return;
  order_.resize(items_.size());
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.reserve(2 * items_.size() / kLeafItems + 2);
  build(0, static_cast<int32_t>(items_.size()), 0);
}

int32_t ConeTree::build(int32_t first, int32_t count, int depth) {
  const auto index = static_cast<int32_t>(nodes_.size());
  nodes_.emplace_back();
  // The node's box holds its items' boxes; its cone's axis is their axes' mean and its
  // half-angle the largest of an item's axis's angle from it plus the item's own.
  BoxCone bound;
  Vec3 axes{0, 0, 0};
  BoundingBox centres;
  for (int32_t i = first; i < first + count; ++i) {
    const BoxCone& item = items_[static_cast<size_t>(order_[static_cast<size_t>(i)])];
    bound.box.add(item.box);
    axes += item.axis;
    centres.add(item.box.center());
  }
  bound.axis = length(axes) > 1e-9 ? normalize(axes) : Vec3{0, 0, 1};
  double spread = 0;
  for (int32_t i = first; i < first + count && spread < kPi; ++i) {
    const BoxCone& item = items_[static_cast<size_t>(order_[static_cast<size_t>(i)])];
    spread = std::max(spread, angle_between(bound.axis, item.axis) + std::acos(std::clamp(item.cos_spread, -1.0, 1.0)));
  }
  bound.cos_spread = spread >= kPi ? -1.0 : std::cos(spread);
  nodes_[static_cast<size_t>(index)].cone = bound;
  if (count <= kLeafItems || depth >= kMaxDepth) {
    nodes_[static_cast<size_t>(index)].first = first;
    nodes_[static_cast<size_t>(index)].count = count;
    return index;
  }
  // Halved at the median of the items' centres along the widest side.
  const Vec3 extent = centres.size();
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const int32_t half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](int32_t a, int32_t b) {
                     const double ca = items_[static_cast<size_t>(a)].box.center()[axis];
                     const double cb = items_[static_cast<size_t>(b)].box.center()[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const int32_t left = build(first, half, depth + 1);
  const int32_t right = build(first + half, count - half, depth + 1);
  nodes_[static_cast<size_t>(index)].first = left;
  nodes_[static_cast<size_t>(index)].second_child = right;
  return index;
}

}  // namespace skylit
