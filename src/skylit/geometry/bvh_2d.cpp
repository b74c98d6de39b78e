// The 2-D BVH's builder (bvh_2d.h).
#include "skylit/geometry/bvh_2d.h"

#include <algorithm>
#include <limits>

namespace skylit {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr size_t kLeafSize = 4;
constexpr size_t kMaxLeafSize = 16;
constexpr int kBins = 16;

double half_perimeter(const double lo[2], const double hi[2]) { return (hi[0] - lo[0]) + (hi[1] - lo[1]); }

// Binned surface-area heuristic in 2-D (bvh_2d.h): perimeter is the cost.
class BvhBuilder {
 public:
  BvhBuilder(std::vector<Bvh2dItem>& items, std::vector<Bvh2dNode>& nodes) : items_(items), nodes_(nodes) {}

  void build(size_t begin, size_t end, int depth) {
    const size_t node = nodes_.size();
    nodes_.push_back({});
    Bvh2dNode bounds{{kInf, kInf}, {-kInf, -kInf}, -kInf, 0, 0};
    double clo[2] = {kInf, kInf}, chi[2] = {-kInf, -kInf};
    for (size_t i = begin; i < end; ++i) {
      const Bvh2dItem& f = items_[i];
      for (int k = 0; k < 2; ++k) {
        bounds.lo[k] = std::min(bounds.lo[k], f.lo[k]);
        bounds.hi[k] = std::max(bounds.hi[k], f.hi[k]);
        clo[k] = std::min(clo[k], f.centre[k]);
        chi[k] = std::max(chi[k], f.centre[k]);
      }
      bounds.top = std::max(bounds.top, f.top);
    }
    const size_t count = end - begin;
    bounds.index = static_cast<uint32_t>(begin);
    bounds.count = static_cast<uint32_t>(count);
    if (count <= kLeafSize || depth >= kBvh2dMaxDepth) {
      nodes_[node] = bounds;
      return;
    }

    int best_axis = -1, best_bin = 0;
    double best_cost = kInf;
    for (int axis = 0; axis < 2; ++axis) {
      const double extent = chi[axis] - clo[axis];
      if (!(extent > 0)) continue;
      struct Bin {
        double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
        size_t n = 0;
      } bins[kBins];
      for (size_t i = begin; i < end; ++i) {
        Bin& b = bins[bin_of(items_[i], axis, clo[axis], extent)];
        ++b.n;
        for (int k = 0; k < 2; ++k) {
          b.lo[k] = std::min(b.lo[k], items_[i].lo[k]);
          b.hi[k] = std::max(b.hi[k], items_[i].hi[k]);
        }
      }
      // Cost of splitting after bin s: right side swept first, then the left.
      double right_cost[kBins];
      Bin acc;
      for (int s = kBins - 1; s > 0; --s) {
        grow(acc, bins[s]);
        right_cost[s] = acc.n ? half_perimeter(acc.lo, acc.hi) * acc.n : kInf;
      }
      acc = Bin{};
      for (int s = 0; s < kBins - 1; ++s) {
        grow(acc, bins[s]);
        if (acc.n == 0) continue;
        const double cost = half_perimeter(acc.lo, acc.hi) * acc.n + right_cost[s + 1];
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bin = s;
        }
      }
    }
    const bool worth_it = best_cost < half_perimeter(bounds.lo, bounds.hi) * count;
    if (best_axis < 0 || (!worth_it && count <= kMaxLeafSize)) {
      nodes_[node] = bounds;
      return;
    }

    auto first = items_.begin() + static_cast<ptrdiff_t>(begin);
    auto last = items_.begin() + static_cast<ptrdiff_t>(end);
    const double extent = chi[best_axis] - clo[best_axis];
    auto middle = std::partition(
        first, last, [&](const Bvh2dItem& f) { return bin_of(f, best_axis, clo[best_axis], extent) <= best_bin; });
    if (middle == first || middle == last) {  // cannot happen with a finite best_cost; be safe
      middle = first + static_cast<ptrdiff_t>(count / 2);
      std::nth_element(first, middle, last, [&](const Bvh2dItem& a, const Bvh2dItem& b) {
        return a.centre[best_axis] < b.centre[best_axis];
      });
    }
    const size_t mid = static_cast<size_t>(middle - items_.begin());
    build(begin, mid, depth + 1);
    bounds.index = static_cast<uint32_t>(nodes_.size());
    bounds.count = 0;
    build(mid, end, depth + 1);
    nodes_[node] = bounds;
  }

 private:
  template <typename Bin>
  static void grow(Bin& acc, const Bin& b) {
    acc.n += b.n;
    for (int k = 0; k < 2; ++k) {
      acc.lo[k] = std::min(acc.lo[k], b.lo[k]);
      acc.hi[k] = std::max(acc.hi[k], b.hi[k]);
    }
  }
  static int bin_of(const Bvh2dItem& f, int axis, double lo, double extent) {
    const int b = static_cast<int>((f.centre[axis] - lo) / extent * kBins);
    return std::clamp(b, 0, kBins - 1);
  }

  std::vector<Bvh2dItem>& items_;
  std::vector<Bvh2dNode>& nodes_;
};

}  // namespace

std::vector<Bvh2dNode> build_bvh_2d(std::vector<Bvh2dItem>& items) {
  std::vector<Bvh2dNode> nodes;
  if (items.empty()) return nodes;
  nodes.reserve(2 * items.size() / kLeafSize + 1);
  BvhBuilder(items, nodes).build(0, items.size(), 0);
  return nodes;
}

}  // namespace skylit
