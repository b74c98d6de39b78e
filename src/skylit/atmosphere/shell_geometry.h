// Rays in a spherical shell, described as in Bruneton (2017) by the distance r of
// their origin from the Earth's centre and the cosine μ of their zenith angle.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace skylit::shell {

// Distance along the ray (r, μ) to the sphere of radius `radius` that encloses it
// (radius ≥ r): the far intersection.
inline double distance_to_outer_sphere(double r, double mu, double radius) {
  const double discriminant = r * r * (mu * mu - 1.0) + radius * radius;
  return std::max(0.0, -r * mu + std::sqrt(std::max(0.0, discriminant)));
}

// Whether the ray (r, μ) meets the sphere of radius `ground` below it.
inline bool hits_ground(double r, double mu, double ground) {
  return mu < 0.0 && r * r * (mu * mu - 1.0) + ground * ground >= 0.0;
}

// Distance to the near intersection with the inner sphere `ground` (only when hits_ground).
inline double distance_to_ground(double r, double mu, double ground) {
  const double discriminant = r * r * (mu * mu - 1.0) + ground * ground;
  return std::max(0.0, -r * mu - std::sqrt(std::max(0.0, discriminant)));
}

// Radius and zenith cosine after travelling t along the ray (r, μ).
inline double radius_at(double r, double mu, double t) {
  return std::sqrt(std::max(0.0, r * r + t * t + 2.0 * r * mu * t));
}
inline double mu_at(double r, double mu, double t, double r_t) { return std::clamp((r * mu + t) / r_t, -1.0, 1.0); }

// Segment boundaries 0 = t₀ < … < t_n = length for integrating along a ray, crowded
// (quadratically) toward t_low, where the ray is lowest and the air densest: t_low − t_low·u²
// before it and t_low + (length − t_low)·u² after it, with the segments shared out in
// proportion to the two parts' lengths.
inline std::vector<double> crowded_boundaries(double length, double t_low, int segments) {
  t_low = std::clamp(t_low, 0.0, length);
  const int before = t_low > 0 ? std::max(1, static_cast<int>(segments * t_low / length)) : 0;
  const int after = std::max(1, segments - before);
  std::vector<double> t{0.0};
  for (int k = 1; k <= before; ++k) {
    const double u = 1.0 - static_cast<double>(k) / before;
    t.push_back(t_low - t_low * u * u);
  }
  for (int k = 1; k <= after; ++k) {
    const double u = static_cast<double>(k) / after;
    t.push_back(t_low + (length - t_low) * u * u);
  }
  return t;
}

}  // namespace skylit::shell
