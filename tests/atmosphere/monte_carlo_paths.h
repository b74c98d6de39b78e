// Pieces shared by the Monte Carlo references of the atmosphere in
// multiple_scattering_test.cpp (the collision estimator, MonteCarloSky, and the
// estimator along the sunlit part of each free flight, sunlit_line_sky.h): random
// numbers, direction sampling, the views compared, and means with standard errors.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "skylit/atmosphere/phase_functions.h"
#include "skylit/core/vec3.h"

namespace skylit::test_reference {

// splitmix64 (Steele, Lea & Flood 2014): small, fast, same numbers everywhere.
struct Random {
  uint64_t state;
  double uniform() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

// The direction at angle acos(cos_theta) from `axis`, at azimuth phi about it.
inline Vec3 around(const Vec3& axis, double cos_theta, double phi) {
  const Vec3 helper = std::abs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 t = normalize(cross(axis, helper)), b = cross(axis, t);
  const double s = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return t * (s * std::cos(phi)) + b * (s * std::sin(phi)) + axis * cos_theta;
}

// Inverse CDF of Henyey–Greenstein's cos θ.
inline double sample_henyey_greenstein(double g, double u) {
  if (std::abs(g) < 1e-3) return 1.0 - 2.0 * u;
  const double q = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
  return (1.0 + g * g - q * q) / (2.0 * g);
}

// The next collision of a free flight by delta tracking (Woodcock et al. 1965):
// tentative collisions at the rate `majorant` (at least σ_t everywhere along the ray),
// each real with probability σ_t(t)/majorant. The distance of the first real one, or
// nothing if the flight passes t_max first.
template <class ExtinctionAt>
std::optional<double> next_collision(double t_max, double majorant, Random& random, const ExtinctionAt& extinction_at) {
  double t = 0;
  for (;;) {
    t -= std::log(1.0 - random.uniform()) / majorant;
    if (t >= t_max) return std::nullopt;
    if (random.uniform() * majorant < extinction_at(t)) return t;
  }
}

// One view: a direction (elevation, azimuth from the sun), or the horizontal plane
// (paths start cosine-distributed over the upper hemisphere with weight π, so the
// estimate is the diffuse horizontal irradiance per unit solar irradiance).
struct View {
  const char* name;
  double elevation_deg, azimuth_from_sun_deg;
  bool horizontal_plane;
};
inline constexpr std::array<View, 6> kViews{{{"zenith", 90, 0, false},
                                             {"45 deg toward the sun", 45, 0, false},
                                             {"45 deg away from the sun", 45, 180, false},
                                             {"20 deg, 90 deg from the sun", 20, 90, false},
                                             {"10 deg away from the sun", 10, 180, false},
                                             {"horizontal plane", 90, 0, true}}};

struct Estimate {
  double mean = 0, standard_error = 0;
};

// The mean over all paths of slot `slot` and its standard error from the spread of the
// chunks' means (each chunk an independent, equally large estimate), in chunk order:
// deterministic.
inline Estimate estimate_from_chunks(const std::vector<std::vector<double>>& chunk_sums, size_t slot,
                                     int paths_per_chunk) {
  const double chunks = static_cast<double>(chunk_sums.size());
  double sum = 0, sum_sq = 0;
  for (const std::vector<double>& c : chunk_sums) {
    const double mean = c[slot] / paths_per_chunk;
    sum += mean;
    sum_sq += mean * mean;
  }
  const double mean = sum / chunks;
  const double variance = std::max(0.0, sum_sq / chunks - mean * mean) * chunks / (chunks - 1);
  return Estimate{mean, std::sqrt(variance / chunks)};
}

}  // namespace skylit::test_reference
