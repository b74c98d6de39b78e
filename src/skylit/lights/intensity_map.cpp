#include "skylit/lights/intensity_map.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace skylit {

IntensityMap::IntensityMap(const Luminaire& luminaire, int resolution)
    : c0_(luminaire.world_direction(0, 90)),
      c90_(luminaire.world_direction(90, 90)),
      nadir_(luminaire.aim()),
      n_(resolution),
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

void IntensityMap::position(double x, double y, double z, double& u, double& v) const {
  const double norm = std::abs(x) + std::abs(y) + std::abs(z);
  double a = x / norm, b = y / norm;
  if (z < 0) {
    const double fa = (1 - std::abs(b)) * (a < 0 ? -1 : 1), fb = (1 - std::abs(a)) * (b < 0 ? -1 : 1);
    a = fa;
    b = fb;
  }
  u = (a + 1) * 0.5 * n_ - 0.5;
  v = (b + 1) * 0.5 * n_ - 0.5;
}

double IntensityMap::candela(const Vec3& d) const {
  if (constant_) return constant_value_;
  double u, v;
  position(dot(d, c0_), dot(d, c90_), dot(d, nadir_), u, v);
  if (!(u == u) || !(v == v)) return 0.0;  // a zero or non-finite direction
  u = std::clamp(u, 0.0, n_ - 1.0);
  v = std::clamp(v, 0.0, n_ - 1.0);
  const int i = std::min(static_cast<int>(u), n_ - 2), j = std::min(static_cast<int>(v), n_ - 2);
  const double fu = u - i, fv = v - j;
  const uint16_t* row = texels_.data() + static_cast<size_t>(j) * n_ + i;
  const double top = row[0] + fu * (row[1] - row[0]);
  const double bottom = row[n_] + fu * (row[n_ + 1] - row[n_]);
  return scale_ * (top + fv * (bottom - top));
}

}  // namespace skylit
