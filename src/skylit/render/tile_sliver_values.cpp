#include "skylit/render/tile_sliver_values.h"

#include <cmath>

#include "skylit/render/cache_corner_agreement.h"

namespace skylit {

const CachedSkyLight* TileSliverValues::find(double x, double y, const SurfacePoint& point) const {
  const Entry* best = nullptr;
  double best_distance = 0;
  // Newest first; entries come row by row, so the scan stops at the first one more than
  // the reach above the sample. An index, not std::ranges::reverse_view, which Clang 14
  // (the sanitizer build) cannot compile with libstdc++ 12.
  for (size_t i = entries_.size(); i-- > 0;) {
    const Entry& entry = entries_[i];
    if (entry.y < y - kReachPixels - 1) break;
    const double d = std::hypot(entry.x - x, entry.y - y);
    if (d > kReachPixels || !same_surface(entry.point, point) || !within_reach(entry.point, point)) continue;
    if (!best || d < best_distance) {  // ties keep the newest: deterministic
      best = &entry;
      best_distance = d;
    }
  }
  return best ? &best->value : nullptr;
}

void TileSliverValues::add(double x, double y, const SurfacePoint& point, const CachedSkyLight& value) {
  entries_.push_back({x, y, point, value});
}

}  // namespace skylit
