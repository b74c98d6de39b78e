// The sun-depth grid (sun_depth_grid.h): each node marched (cloud_march.h) toward the
// sun when a look-up first needs it, read by trilinear interpolation.
#include "skylit/clouds/sun_depth_grid.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

#include "skylit/clouds/cloud_march.h"

namespace skylit {

void SunDepthGrid::prepare(const CloudGeometry& cloud, const Vec3& to_sun) {
  depths_.clear();
  const double len = length(to_sun);
  if (cloud.empty() || !(len > 0) || !std::isfinite(len)) return;
  to_sun_ = to_sun / len;
  depths_.assign(2 * static_cast<std::size_t>(kSunGridU) * kSunGridV * kSunGridZ, kNotMarched);
}

double SunDepthGrid::node(const CloudGeometry& cloud, int i, int j, int k, int line) const {
  std::atomic_ref<float> slot(depths_[2 * ((static_cast<std::size_t>(k) * kSunGridV + j) * kSunGridU + i) + line]);
  const float stored = slot.load(std::memory_order_relaxed);
  if (stored != kNotMarched) return stored;
  const CloudShape& shape = cloud.shape();
  const double a = shape.semi_axis_a, b = shape.semi_axis_b, tm = shape.max_thickness;
  const double u = -a + 2 * a * i / (kSunGridU - 1), v = -b + 2 * b * j / (kSunGridV - 1);
  const double z = shape.altitude - 0.5 * tm + tm * k / (kSunGridZ - 1);
  const auto value = static_cast<float>(cloud_optical_depth(
      cloud, cloud.world_point(u, v, z), line == 0 ? to_sun_ : -to_sun_, 0.0, std::numeric_limits<double>::infinity()));
  slot.store(value, std::memory_order_relaxed);
  return value;
}

bool SunDepthGrid::prepared_for(const Vec3& to_sun) const {
  if (depths_.empty()) return false;
  const double len = length(to_sun);
  if (!(len > 0) || !std::isfinite(len)) return false;
  const Vec3 d = to_sun / len;
  return std::abs(d.x - to_sun_.x) <= 1e-12 && std::abs(d.y - to_sun_.y) <= 1e-12 && std::abs(d.z - to_sun_.z) <= 1e-12;
}

int SunDepthGrid::marched_nodes() const {
  return static_cast<int>(std::count_if(depths_.begin(), depths_.end(), [](float& d) {
    return std::atomic_ref<float>(d).load(std::memory_order_relaxed) != kNotMarched;
  }));
}

SunLineDepth SunDepthGrid::depths_at(const CloudGeometry& cloud, const Vec3& p, bool away) const {
  if (depths_.empty()) return {};
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
  const int lines = away ? 2 : 1;
  // The cell's eight nodes, read as they are; those not yet marched (rare once a cloud
  // has been looked at) are marched here.
  std::array<std::array<double, 8>, 2> corner{};
  for (int c = 0; c < 8; ++c) {
    const int ci = i + (c & 1), cj = j + ((c >> 1) & 1), ck = k + (c >> 2);
    const std::size_t index = 2 * ((static_cast<std::size_t>(ck) * kSunGridV + cj) * kSunGridU + ci);
    for (int line = 0; line < lines; ++line) {
      const float stored = std::atomic_ref<float>(depths_[index + line]).load(std::memory_order_relaxed);
      corner[line][c] = stored != kNotMarched ? stored : node(cloud, ci, cj, ck, line);
    }
  }
  auto interpolate = [&](const std::array<double, 8>& at) {
    auto plane = [&](int z) {
      const double c0 = at[4 * z] + fu * (at[4 * z + 1] - at[4 * z]);
      const double c1 = at[4 * z + 2] + fu * (at[4 * z + 3] - at[4 * z + 2]);
      return c0 + fv * (c1 - c0);
    };
    const double p0 = plane(0), p1 = plane(1);
    return std::max(0.0, p0 + fz * (p1 - p0));
  };
  return {interpolate(corner[0]), away ? interpolate(corner[1]) : 0.0};
}

}  // namespace skylit
