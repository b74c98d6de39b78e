#include "skylit/sky/band_sources.h"

#include <algorithm>
#include <cmath>

namespace skylit {

BandSources::BandSources(int bands, int segments) : bands_(bands), segments_(segments) {
  // Tilt edges: cos δ falls by 2/N from band to band over the sky (δ ∈ [0, π]); the
  // ground's half mirrors them (δ ∈ [π, 2π]).
  for (int k = 0; k <= bands; ++k) tilt_edges_.push_back(std::acos(std::clamp(1.0 - 2.0 * k / bands, -1.0, 1.0)));
  for (int k = 1; k <= bands; ++k) tilt_edges_.push_back(kPi + tilt_edges_[static_cast<size_t>(k)]);
  // Along a band, equal steps in cos α give elements of equal solid angle.
  for (int j = 0; j <= segments; ++j)
    alpha_edges_.push_back(std::acos(std::clamp(1.0 - 2.0 * j / segments, -1.0, 1.0)));
  for (int j = 0; j < segments; ++j) alpha_.push_back(std::acos(1.0 - 2.0 * (j + 0.5) / segments));
  for (int l = 0; l < 2 * bands; ++l) {
    const double lo = tilt_edges_[static_cast<size_t>(l)], hi = tilt_edges_[static_cast<size_t>(l + 1)];
    tilt_.push_back(0.5 * (lo + hi));
    half_width_.push_back(0.5 * (hi - lo));
    for (int j = 0; j < segments; ++j) {
      const double a = alpha_[static_cast<size_t>(j)], d = tilt_.back();
      // ∫ sin α dα over the segment is 2/M; times the band's width in δ.
      const double solid_angle = (2.0 / segments) * (hi - lo);
      elements_.push_back({{std::cos(a), std::sin(a) * std::cos(d), std::sin(a) * std::sin(d)}, solid_angle, l, j});
    }
  }
}

std::vector<SkyElement> fibonacci_sphere(int count) {
  std::vector<SkyElement> out;
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.push_back({{r * std::cos(golden_angle * i), r * std::sin(golden_angle * i), z}, 4.0 * kPi / count, -1, i});
  }
  return out;
}

void BandSources::locate(const Vec3& direction, int& band, int& segment) const {
  const Vec3 d = normalize(direction);
  double tilt = std::atan2(d.z, d.y);  // the sample plane through the x axis containing d
  if (tilt < 0) tilt += 2.0 * kPi;
  band = static_cast<int>(std::upper_bound(tilt_edges_.begin(), tilt_edges_.end(), tilt) - tilt_edges_.begin()) - 1;
  band = std::clamp(band, 0, 2 * bands_ - 1);
  segment = static_cast<int>(std::floor((1.0 - std::clamp(d.x, -1.0, 1.0)) * 0.5 * segments_));
  segment = std::clamp(segment, 0, segments_ - 1);
}

}  // namespace skylit
