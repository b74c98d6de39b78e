#include "skylit/clouds/cloud_layer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace skylit {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

double finite_or(double x, double fallback) { return std::isfinite(x) ? x : fallback; }
}  // namespace

double expected_generated_cloud_count(const CloudLayerSettings& s) {
  const double coverage = std::clamp(finite_or(s.coverage, 0.0), 0.0, 0.995);
  const double lo = std::min(s.min_semi_axis, s.max_semi_axis), hi = std::max(s.min_semi_axis, s.max_semi_axis);
  const double aspect = std::clamp(finite_or(s.min_aspect, 1.0), 0.05, 1.0);
  const double wide = std::max(0.0, s.half_extent) + hi;
  const double mean_footprint = kPi * (lo * lo + lo * hi + hi * hi) / 3.0 * (1.0 + aspect) / 2.0;
  if (!(mean_footprint > 0) || coverage <= 0) return 0.0;
  return -std::log1p(-coverage) * (2 * wide) * (2 * wide) / mean_footprint;
}

double cloud_uniform(std::uint64_t draw) { return static_cast<double>(draw >> 11) * 0x1.0p-53; }

CloudLayer CloudLayer::generate(const CloudLayerSettings& in) {
  CloudLayerSettings s = in;
  const double coverage = std::clamp(finite_or(s.coverage, 0.0), 0.0, 1.0);
  double lo = std::max(0.0, finite_or(s.min_semi_axis, 0.0)), hi = std::max(0.0, finite_or(s.max_semi_axis, 0.0));
  if (lo > hi) std::swap(lo, hi);
  double t_lo = std::max(0.0, finite_or(s.min_thickness, 0.0)), t_hi = std::max(0.0, finite_or(s.max_thickness, 0.0));
  if (t_lo > t_hi) std::swap(t_lo, t_hi);
  const double aspect = std::clamp(finite_or(s.min_aspect, 1.0), 0.05, 1.0);
  const double half = std::max(0.0, finite_or(s.half_extent, 0.0));
  const int waves = std::clamp(s.waves, 0, 16);
  const double amp0 = std::clamp(finite_or(s.first_amplitude, 0.0), 0.0, 1.0);

  std::vector<Cloud> clouds;
  if (coverage <= 0 || hi <= 0 || half <= 0) return CloudLayer(std::move(clouds));
  const double wide = half + hi;
  const double target = -std::log1p(-std::min(coverage, 0.995)) * (2 * wide) * (2 * wide);

  std::mt19937_64 rng(s.seed);
  auto uniform = [&](double a, double b) { return a + (b - a) * cloud_uniform(rng()); };
  double area = 0;
  while (area < target && clouds.size() < 2 * kMaxGeneratedClouds) {
    CloudShape c;
    c.center_x = finite_or(s.center_x, 0.0) + uniform(-wide, wide);
    c.center_y = finite_or(s.center_y, 0.0) + uniform(-wide, wide);
    c.altitude = finite_or(s.altitude, 1500.0);
    c.semi_axis_a = uniform(lo, hi);
    c.semi_axis_b = c.semi_axis_a * uniform(aspect, 1.0);
    c.rotation = uniform(0.0, kPi);
    c.max_thickness = uniform(t_lo, t_hi);
    c.extinction = s.extinction;
    add_gardner_waves(c, rng(), waves, amp0);
    area += kPi * c.semi_axis_a * c.semi_axis_b;
    clouds.emplace_back(c);
  }
  return CloudLayer(std::move(clouds));
}

void add_gardner_waves(CloudShape& c, std::uint64_t seed, int waves, double first_amplitude) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double a, double b) { return a + (b - a) * cloud_uniform(rng()); };
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<CloudWave>& series = axis == 0 ? c.waves_u : c.waves_v;
    const double base = 2 * kPi / ((axis == 0 ? c.semi_axis_a : c.semi_axis_b) * uniform(0.8, 1.25));
    double amp = first_amplitude;
    for (int i = 0; i < std::clamp(waves, 0, 16); ++i) {
      series.push_back({amp, base * std::ldexp(1.0, i), uniform(0.0, 2 * kPi)});
      amp *= 0.70710678118654752;
    }
  }
}

void CloudLayer::prepare_sun(const Vec3& to_sun) {
  clear_sun();
  grid_sun_ = to_sun;
  grid_built_ = std::make_unique<std::once_flag[]>(clouds_.size());
}

void CloudLayer::clear_sun() {
  grid_sun_.reset();
  grid_built_.reset();
  for (Cloud& c : clouds_) c.clear_sun();
}

void CloudLayer::ensure_sun_grid(std::size_t index) const {
  if (!grid_sun_) return;  // Cloud::scatter then uses the grid if light.to_sun is its direction
  std::call_once(grid_built_[index], [&] { clouds_[index].prepare_sun(*grid_sun_); });
}

std::vector<CloudLayer::Crossing> CloudLayer::crossings(const Vec3& o, const Vec3& d, double t_min,
                                                        double t_max) const {
  std::vector<Crossing> out;
  thread_local std::vector<std::uint32_t> candidates;  // reused: this runs for every ray
  grid_.candidates(o, d, t_min, t_max, candidates);
  for (const std::uint32_t i : candidates) {
    double t0, t1;
    if (clouds_[i].clip(o, d, t_min, t_max, t0, t1)) out.push_back({i, t0, t1});
  }
  std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) {
    return a.t_enter < b.t_enter || (a.t_enter == b.t_enter && a.index < b.index);
  });
  return out;
}

std::optional<CloudLayer::Crossing> CloudLayer::first_hit(const Vec3& o, const Vec3& d, double t_min,
                                                          double t_max) const {
  for (const Crossing& c : crossings(o, d, t_min, t_max)) {
    double first = kInf;
    march_cloud_inside(clouds_[c.index], o, d, c.t_enter, c.t_exit, [&](double s0, double s1) {
      if (s1 > s0) first = std::min(first, s0);
    });
    if (first < kInf) return c;
  }
  return std::nullopt;
}

double CloudLayer::optical_depth(const Vec3& o, const Vec3& d, double t_min, double t_max) const {
  double sum = 0;
  for (const Crossing& c : crossings(o, d, t_min, t_max))
    sum += clouds_[c.index].optical_depth(o, d, c.t_enter, c.t_exit);
  return sum;
}

double CloudLayer::sun_transmittance(const Vec3& p, const Vec3& to_sun) const {
  return std::exp(-optical_depth(p, to_sun, 0.0, kInf));
}

CloudScattering CloudLayer::scatter(const Vec3& o, const Vec3& d, double t_min, double t_max,
                                    const CloudLighting& light) const {
  CloudScattering out;
  for (const Crossing& c : crossings(o, d, t_min, t_max)) {
    ensure_sun_grid(c.index);
    const CloudScattering s = clouds_[c.index].scatter(o, d, c.t_enter, c.t_exit, light);
    if (!std::isfinite(out.distance) && (s.transmittance < 1.0 || !s.in_scattered.is_black()))
      out.distance = std::max(c.t_enter, t_min);
    out.in_scattered += s.in_scattered * static_cast<float>(out.transmittance);
    out.transmittance *= s.transmittance;
    // The clouds behind are seen through less than a millionth: what they add is below
    // the float spectra's own rounding of the clouds in front (a dense layer seen low
    // crosses dozens of clouds behind the first).
    if (out.transmittance < kOpaqueTransmittance) break;
  }
  return out;
}

}  // namespace skylit
