// The cloud's solid (cloud_shape.h): the shape made safe, its texture tables and their
// bounds, the thickness, and the clip of a ray to the bounding volume.
#include "skylit/clouds/cloud_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double finite_nonnegative(double x) { return std::isfinite(x) && x > 0 ? x : 0.0; }

// Horizontal steps per the smaller semi-axis and per wavelength of the finest wave
// (docs/clouds.md): the march's step along the horizontal, horizontal_scale().
constexpr double kStepsPerSemiAxis = 64.0;
constexpr double kStepsPerWavelength = 32.0;

}  // namespace

CloudGeometry::CloudGeometry(const CloudShape& shape) : shape_(shape) {
  shape_.semi_axis_a = finite_nonnegative(shape_.semi_axis_a);
  shape_.semi_axis_b = finite_nonnegative(shape_.semi_axis_b);
  shape_.max_thickness = finite_nonnegative(shape_.max_thickness);
  shape_.extinction = finite_nonnegative(shape_.extinction);
  shape_.albedo = std::clamp(finite_nonnegative(shape_.albedo), 0.0, 1.0);
  if (!std::isfinite(shape_.falloff_exponent) || shape_.falloff_exponent < 0) shape_.falloff_exponent = 0.5;
  if (!std::isfinite(shape_.rotation)) shape_.rotation = 0;
  if (!std::isfinite(shape_.altitude)) shape_.altitude = 0;
  if (!std::isfinite(shape_.center_x)) shape_.center_x = 0;
  if (!std::isfinite(shape_.center_y)) shape_.center_y = 0;
  cos_r_ = std::cos(shape_.rotation);
  sin_r_ = std::sin(shape_.rotation);

  const double a = shape_.semi_axis_a, b = shape_.semi_axis_b;
  horizontal_scale_ = std::min(a, b) / kStepsPerSemiAxis;
  auto texture_norm = [&](std::vector<CloudWave>& waves) {
    double sum = 0;
    for (CloudWave& w : waves) {
      if (!std::isfinite(w.amplitude)) w.amplitude = 0;
      if (!std::isfinite(w.frequency)) w.frequency = 0;
      if (!std::isfinite(w.phase)) w.phase = 0;
      sum += std::abs(w.amplitude);
      if (w.amplitude != 0 && w.frequency != 0)
        horizontal_scale_ = std::min(horizontal_scale_, 2.0 * kPi / std::abs(w.frequency) / kStepsPerWavelength);
    }
    return 1.0 + sum;
  };
  norm_u_ = texture_norm(shape_.waves_u);
  norm_v_ = texture_norm(shape_.waves_v);
  for (int i = 0; i <= kTextureSamples; ++i) {
    const double t = -1.0 + 2.0 * i / kTextureSamples;
    texture_u_.push_back(texture(t * a, shape_.waves_u, norm_u_));
    texture_v_.push_back(texture(t * b, shape_.waves_v, norm_v_));
  }
  // The tables are what the march samples: piecewise linear, so their slope is at most
  // the largest slope of one interval (cloud_margin_bounds uses it as a Lipschitz constant).
  auto table_slope = [](const std::vector<double>& table, double half_width) {
    double rise = 0;
    for (std::size_t i = 0; i + 1 < table.size(); ++i) rise = std::max(rise, std::abs(table[i + 1] - table[i]));
    return half_width > 0 ? rise / (2.0 * half_width / kTextureSamples) : 0.0;
  };
  texture_slope_u_ = table_slope(texture_u_, a);
  texture_slope_v_ = table_slope(texture_v_, b);
  // |f''| ≤ Σ |a_i| ω_i² / (1 + Σ |a_i|) where f is smooth, i.e. where max(0, ·) never
  // clips it: when Σ |a_i| < 1. Otherwise no curvature bound (infinite).
  auto texture_curvature = [](const std::vector<CloudWave>& waves, double norm) {
    double sum = 0;
    for (const CloudWave& w : waves) sum += std::abs(w.amplitude) * w.frequency * w.frequency;
    return norm < 2.0 ? sum / norm : kInf;
  };
  texture_curvature_u_ = texture_curvature(shape_.waves_u, norm_u_);
  texture_curvature_v_ = texture_curvature(shape_.waves_v, norm_v_);
  // Half-widths of the box around the rotated ellipse.
  extent_x_ = std::hypot(a * cos_r_, b * sin_r_);
  extent_y_ = std::hypot(a * sin_r_, b * cos_r_);
  empty_ = !(a > 0 && b > 0 && shape_.max_thickness > 0 && horizontal_scale_ > 0);
}

double CloudGeometry::texture(double w, const std::vector<CloudWave>& waves, double norm) {
  double f = 1.0;
  for (const CloudWave& wave : waves) f += wave.amplitude * std::sin(wave.frequency * w + wave.phase);
  return std::max(0.0, f) / norm;
}

double CloudGeometry::table_lookup(const std::vector<double>& table, double w, double half_width) {
  const double f = std::clamp((w / half_width + 1.0) * 0.5, 0.0, 1.0) * kTextureSamples;
  const int i = std::min(static_cast<int>(f), kTextureSamples - 1);
  const double t = f - i;
  return table[static_cast<size_t>(i)] * (1 - t) + table[static_cast<size_t>(i + 1)] * t;
}

double CloudGeometry::envelope(double q) const {
  if (!(q > 0)) return 0.0;
  return shape_.falloff_exponent == 0.5 ? std::sqrt(q) : std::pow(q, shape_.falloff_exponent);
}

double CloudGeometry::local_thickness(double u, double v) const {
  if (empty_) return 0.0;
  const double ua = u / shape_.semi_axis_a, vb = v / shape_.semi_axis_b;
  const double q = 1.0 - (ua * ua + vb * vb);
  if (!(q > 0)) return 0.0;
  return shape_.max_thickness * envelope(q) * table_lookup(texture_u_, u, shape_.semi_axis_a) *
         table_lookup(texture_v_, v, shape_.semi_axis_b);
}

double CloudGeometry::thickness(double x, double y) const {
  const double dx = x - shape_.center_x, dy = y - shape_.center_y;
  return local_thickness(along_u(dx, dy), along_v(dx, dy));
}

bool CloudGeometry::contains(const Vec3& p) const {
  const double t = thickness(p.x, p.y);
  return t > 0 && std::abs(p.z - shape_.altitude) <= 0.5 * t;
}

bool CloudGeometry::clip(const Vec3& o, const Vec3& d, double t_min, double t_max, double& t0, double& t1) const {
  if (empty_ || !(t_max > t_min)) return false;
  double lo = t_min, hi = t_max;
  // Slab |z − z_mid| ≤ T_max/2.
  const double half = 0.5 * shape_.max_thickness;
  const double z0 = shape_.altitude - half, z1 = shape_.altitude + half;
  if (std::abs(d.z) < 1e-300) {
    if (o.z < z0 || o.z > z1) return false;
  } else {
    double a = (z0 - o.z) / d.z, b = (z1 - o.z) / d.z;
    if (a > b) std::swap(a, b);
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
  if (!(hi > lo)) return false;
  // Elliptic cylinder r < 1, in coordinates scaled by the semi-axes.
  const double dx = o.x - shape_.center_x, dy = o.y - shape_.center_y;
  const double u = along_u(dx, dy) / shape_.semi_axis_a;
  const double v = along_v(dx, dy) / shape_.semi_axis_b;
  const double du = along_u(d.x, d.y) / shape_.semi_axis_a;
  const double dv = along_v(d.x, d.y) / shape_.semi_axis_b;
  const double qa = du * du + dv * dv, qb = u * du + v * dv, qc = u * u + v * v - 1.0;
  if (!(qa > 1e-300)) {
    if (qc >= 0) return false;
  } else {
    const double disc = qb * qb - qa * qc;
    if (!(disc > 0)) return false;
    const double root = std::sqrt(disc);
    const double q = qb >= 0 ? -(qb + root) : -(qb - root);  // stable roots of qa t² + 2 qb t + qc
    double ta = q / qa, tb = q != 0 ? qc / q : -ta;
    if (ta > tb) std::swap(ta, tb);
    lo = std::max(lo, ta);
    hi = std::min(hi, tb);
  }
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return false;
  t0 = lo;
  t1 = hi;
  return true;
}

}  // namespace skylit
