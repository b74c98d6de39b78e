#include "skylit/lights/intensity_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace skylit {

IntensityMap::IntensityMap(const Luminaire& luminaire, int resolution)
    : c0_(luminaire.world_direction(0, 90)),
      c90_(luminaire.world_direction(90, 90)),
      nadir_(luminaire.aim()),
      n_(resolution),
      half_n_(0.5 * resolution),
      constant_(luminaire.distribution().kind() == IntensityDistribution::Kind::kIsotropic),
      constant_value_(luminaire.intensity(luminaire.aim())) {
  if (constant_) return;
  std::vector<double> exact(static_cast<size_t>(n_) * n_, 0.0);
  // Beyond the distribution's widest angle the intensity is 0: no need to look it up.
  const double cos_beyond = std::cos(std::min(180.0, luminaire.distribution().max_gamma_deg() + 1.0) * kPi / 180);
  tbb::parallel_for(0, n_, [&](int j) {
    for (int i = 0; i < n_; ++i) {
      // The texel centre's map coordinates in [−1, 1]², unfolded to a direction.
      const double a = (i + 0.5) / n_ * 2 - 1, b = (j + 0.5) / n_ * 2 - 1;
      double x = a, y = b, z = 1 - std::abs(a) - std::abs(b);
      if (z < 0) {  // the upper hemisphere, folded into the corners
        x = (1 - std::abs(b)) * (a < 0 ? -1 : 1);
        y = (1 - std::abs(a)) * (b < 0 ? -1 : 1);
      }
      if (z / std::sqrt(x * x + y * y + z * z) < cos_beyond) continue;
      const Vec3 direction = x * c0_ + y * c90_ + z * nadir_;
      exact[static_cast<size_t>(j) * n_ + i] = luminaire.intensity(direction);
    }
  });
  const double peak = *std::max_element(exact.begin(), exact.end());
  scale_ = peak > 0 ? peak / 65535.0 : 0.0;
  texels_.resize(exact.size());
  for (size_t k = 0; k < exact.size(); ++k)
    texels_[k] = static_cast<uint16_t>(scale_ > 0 ? std::lround(exact[k] / scale_) : 0);
}

double IntensityMap::candela(const Vec3& d) const {
  if (constant_) return constant_value_;
  // The direction in the luminaire's frame, onto the octahedron |x| + |y| + |z| = 1,
  // the upper half folded into the square's corners.
  const double x = dot(d, c0_), y = dot(d, c90_), z = dot(d, nadir_);
  const double norm = std::abs(x) + std::abs(y) + std::abs(z);
  if (!(norm > 0) || !(norm < std::numeric_limits<double>::infinity())) return 0.0;
  double a = x / norm, b = y / norm;
  if (z < 0) {
    const double folded_a = std::copysign(1 - std::abs(b), a);
    b = std::copysign(1 - std::abs(a), b);
    a = folded_a;
  }
  const double u = std::clamp((a + 1) * half_n_ - 0.5, 0.0, n_ - 1.0);
  const double v = std::clamp((b + 1) * half_n_ - 0.5, 0.0, n_ - 1.0);
  const int i = std::min(static_cast<int>(u), n_ - 2), j = std::min(static_cast<int>(v), n_ - 2);
  const double fu = u - i, fv = v - j;
  const uint16_t* row = texels_.data() + static_cast<size_t>(j) * n_ + i;
  const double top = row[0] + fu * (row[1] - row[0]);
  const double bottom = row[n_] + fu * (row[n_ + 1] - row[n_]);
  return scale_ * (top + fv * (bottom - top));
}

}  // namespace skylit
