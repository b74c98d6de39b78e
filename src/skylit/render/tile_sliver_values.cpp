#include "skylit/render/tile_sliver_values.h"

#include <cmath>

#include "skylit/render/cache_corner_agreement.h"

namespace skylit {

const CachedSkyLight* TileSliverValues::find(double x, double y, const SurfacePoint& point) const {
  const Entry* best = nullptr;
  double best_distance = 0;
  // Newest first; entries come row by row, so the scan stops at the first one more than
  // the reach above the sample.
  for (auto it = entries_.rbegin(); it != entries_.rend(); ++it) {
    if (it->y < y - kReachPixels - 1) break;
    const double d = std::hypot(it->x - x, it->y - y);
    if (d > kReachPixels || !same_surface(it->point, point) || !within_reach(it->point, point)) continue;
    if (!best || d < best_distance) {  // ties keep the newest: deterministic
      best = &*it;
      best_distance = d;
    }
  }
  return best ? &best->value : nullptr;
}

void TileSliverValues::add(double x, double y, const SurfacePoint& point, const CachedSkyLight& value) {
  entries_.push_back({x, y, point, value});
}

}  // namespace skylit
