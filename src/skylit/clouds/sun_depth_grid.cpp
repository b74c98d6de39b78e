// The sun-depth grid (sun_depth_grid.h): built by marching (cloud_march.h) from every
// node toward the sun, read by trilinear interpolation.
#include "skylit/clouds/sun_depth_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "skylit/clouds/cloud_march.h"

namespace skylit {

void SunDepthGrid::prepare(const CloudGeometry& cloud, const Vec3& to_sun) {
  depths_.clear();
  const double len = length(to_sun);
  if (cloud.empty() || !(len > 0) || !std::isfinite(len)) return;
  to_sun_ = to_sun / len;
  std::vector<float> grid(static_cast<std::size_t>(kSunGridU) * kSunGridV * kSunGridZ);
  const CloudShape& shape = cloud.shape();
  const double a = shape.semi_axis_a, b = shape.semi_axis_b, tm = shape.max_thickness;
  tbb::parallel_for(tbb::blocked_range<int>(0, kSunGridV * kSunGridZ), [&](const tbb::blocked_range<int>& r) {
    for (int jk = r.begin(); jk != r.end(); ++jk) {
      const int j = jk % kSunGridV, k = jk / kSunGridV;
      const double v = -b + 2 * b * j / (kSunGridV - 1);
      const double z = shape.altitude - 0.5 * tm + tm * k / (kSunGridZ - 1);
      for (int i = 0; i < kSunGridU; ++i) {
        const double u = -a + 2 * a * i / (kSunGridU - 1);
        const Vec3 p = cloud.world_point(u, v, z);
        const double value = cloud_optical_depth(cloud, p, to_sun_, 0.0, std::numeric_limits<double>::infinity());
        grid[static_cast<std::size_t>(jk) * kSunGridU + i] = static_cast<float>(value);
      }
    }
  });
  depths_ = std::move(grid);
}

bool SunDepthGrid::prepared_for(const Vec3& to_sun) const {
  if (depths_.empty()) return false;
  const double len = length(to_sun);
  if (!(len > 0) || !std::isfinite(len)) return false;
  const Vec3 d = to_sun / len;
  return std::abs(d.x - to_sun_.x) <= 1e-12 && std::abs(d.y - to_sun_.y) <= 1e-12 && std::abs(d.z - to_sun_.z) <= 1e-12;
}

double SunDepthGrid::depth_at(const CloudGeometry& cloud, const Vec3& p) const {
  if (depths_.empty()) return 0.0;
  const CloudShape& shape = cloud.shape();
  const double dx = p.x - shape.center_x, dy = p.y - shape.center_y;
  const double u = cloud.along_u(dx, dy), v = cloud.along_v(dx, dy);
  const double a = shape.semi_axis_a, b = shape.semi_axis_b, tm = shape.max_thickness;
  auto cell = [](double x, int n, int& i0, double& f) {
    x = std::clamp(std::isfinite(x) ? x : 0.0, 0.0, static_cast<double>(n - 1));
    i0 = std::min(static_cast<int>(x), n - 2);
    f = x - i0;
  };
  int i, j, k;
  double fu, fv, fz;
  cell((u + a) / (2 * a) * (kSunGridU - 1), kSunGridU, i, fu);
  cell((v + b) / (2 * b) * (kSunGridV - 1), kSunGridV, j, fv);
  cell((p.z - shape.altitude + 0.5 * tm) / tm * (kSunGridZ - 1), kSunGridZ, k, fz);
  auto at = [&](int ii, int jj, int kk) {
    return static_cast<double>(depths_[(static_cast<std::size_t>(kk) * kSunGridV + jj) * kSunGridU + ii]);
  };
  auto plane = [&](int kk) {
    const double c0 = at(i, j, kk) + fu * (at(i + 1, j, kk) - at(i, j, kk));
    const double c1 = at(i, j + 1, kk) + fu * (at(i + 1, j + 1, kk) - at(i, j + 1, kk));
    return c0 + fv * (c1 - c0);
  };
  const double p0 = plane(k), p1 = plane(k + 1);
  return std::max(0.0, p0 + fz * (p1 - p0));
}

}  // namespace skylit
