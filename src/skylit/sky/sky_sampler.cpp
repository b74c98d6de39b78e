#include "skylit/sky/sky_sampler.h"

#include <algorithm>
#include <cmath>

namespace skylit {

namespace {

// A floor on each cell's weight, relative to the mean: every direction keeps a chance,
// so that the estimator stays unbiased wherever the table underrates the sky.
constexpr double kFloorShare = 0.02;

Vec3 direction_of(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// The index of the interval of `cdf` (increasing, from 0 to 1) that holds u.
int interval_of(const double* cdf, int size, double u) {
  const double* at = std::upper_bound(cdf, cdf + size + 1, u);
  return std::clamp(static_cast<int>(at - cdf) - 1, 0, size - 1);
}

}  // namespace

SkySampler::SkySampler(const SkyModel& sky)
    : SkySampler([&sky](const Vec3& direction) { return sky.sky_radiance_near_ground(direction).spectrum(); }) {}

SkySampler::SkySampler(const RadianceOf& radiance_of)
    : cell_probability_(kRows * kColumns), row_cdf_(kRows + 1, 0.0), column_cdf_((kColumns + 1) * kRows, 0.0) {
  const double dtheta = kPi / kRows, dphi = 2 * kPi / kColumns;
  // Each cell's radiance (mean over bins) at a 2 × 2 grid inside it, times its solid angle.
  std::vector<double> weight(cell_probability_.size());
  double total = 0;
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kColumns; ++c) {
      double radiance = 0;
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          radiance +=
              radiance_of(direction_of((r + 0.25 + 0.5 * a) * dtheta, (c + 0.25 + 0.5 * b) * dphi)).mean_value() / 4;
      const double solid_angle = (std::cos(r * dtheta) - std::cos((r + 1) * dtheta)) * dphi;
      weight[static_cast<size_t>(r * kColumns + c)] = std::max(0.0, radiance) * solid_angle;
      total += weight[static_cast<size_t>(r * kColumns + c)];
    }
  // With the floor: the floor spread over the sphere in proportion to solid angle.
  double sum = 0;
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kColumns; ++c) {
      const double solid_angle = (std::cos(r * dtheta) - std::cos((r + 1) * dtheta)) * dphi;
      double& w = weight[static_cast<size_t>(r * kColumns + c)];
      w += (total > 0 ? kFloorShare * total : 1.0) * solid_angle / (4 * kPi);
      sum += w;
    }
  for (int r = 0; r < kRows; ++r) {
    double row = 0;
    for (int c = 0; c < kColumns; ++c) {
      const size_t i = static_cast<size_t>(r * kColumns + c);
      cell_probability_[i] = weight[i] / sum;
      row += cell_probability_[i];
      column_cdf_[static_cast<size_t>(r * (kColumns + 1) + c + 1)] = row;
    }
    for (int c = 1; c <= kColumns; ++c) column_cdf_[static_cast<size_t>(r * (kColumns + 1) + c)] /= row;
    row_cdf_[static_cast<size_t>(r + 1)] = row_cdf_[static_cast<size_t>(r)] + row;
  }
  for (double& v : row_cdf_) v /= row_cdf_.back();
}

SkySampler::Sample SkySampler::sample(double u1, double u2) const {
  const int r = interval_of(row_cdf_.data(), kRows, u1);
  const double row_u = (u1 - row_cdf_[static_cast<size_t>(r)]) /
                       std::max(1e-300, row_cdf_[static_cast<size_t>(r + 1)] - row_cdf_[static_cast<size_t>(r)]);
  const double* columns = &column_cdf_[static_cast<size_t>(r * (kColumns + 1))];
  const int c = interval_of(columns, kColumns, u2);
  const double column_u = (u2 - columns[c]) / std::max(1e-300, columns[c + 1] - columns[c]);
  // Uniform in solid angle inside the cell: cos θ uniform, φ uniform.
  const double dtheta = kPi / kRows, dphi = 2 * kPi / kColumns;
  const double cos_top = std::cos(r * dtheta), cos_bottom = std::cos((r + 1) * dtheta);
  const double cos_theta = cos_top + std::clamp(row_u, 0.0, 1.0) * (cos_bottom - cos_top);
  const double phi = (c + std::clamp(column_u, 0.0, 1.0)) * dphi;
  const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  const Vec3 direction{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
  return {direction, pdf(direction)};
}

double SkySampler::pdf(const Vec3& direction) const {
  const double theta = std::acos(std::clamp(direction.z, -1.0, 1.0));
  double phi = std::atan2(direction.y, direction.x);
  if (phi < 0) phi += 2 * kPi;
  const double dtheta = kPi / kRows, dphi = 2 * kPi / kColumns;
  const int r = std::clamp(static_cast<int>(theta / dtheta), 0, kRows - 1);
  const int c = std::clamp(static_cast<int>(phi / dphi), 0, kColumns - 1);
  const double solid_angle = (std::cos(r * dtheta) - std::cos((r + 1) * dtheta)) * dphi;
  return cell_probability_[static_cast<size_t>(r * kColumns + c)] / solid_angle;
}

}  // namespace skylit
