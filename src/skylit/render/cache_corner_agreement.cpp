// corners_agree (cache_corner_agreement.h).
#include "skylit/render/cache_corner_agreement.h"

#include <algorithm>

namespace skylit {

bool within_reach(const SurfacePoint& cached, const SurfacePoint& point) {
  return length(cached.position - point.position) <= kCornerReach * point.distance;
}

bool within_obstacle_reach(const SurfacePoint& cached, double obstacle_distance_m, const SurfacePoint& point,
                           double reach) {
  return length(cached.position - point.position) <= reach * obstacle_distance_m;
}

bool corners_agree(std::span<const double> corner_illuminance_lx, double spread, double other_lx) {
  if (corner_illuminance_lx.empty()) return true;
  const auto [low, high] = std::minmax_element(corner_illuminance_lx.begin(), corner_illuminance_lx.end());
  return *high - *low <= spread * (*high + other_lx);
}

}  // namespace skylit
