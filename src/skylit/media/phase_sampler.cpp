#include "skylit/media/phase_sampler.h"

#include <algorithm>
#include <cmath>

#include "skylit/material/reflection_sampling.h"

namespace skylit {

PhaseSampler::PhaseSampler(const std::function<double(double cos_theta)>& phase)
    : theta_(kRings + 1), cdf_(kRings + 1, 0.0), ring_density_(kRings) {
  // Ring edges θ_i = π (i/N)³: the first ring 5e-11 rad wide, the last 2e-3 rad.
  for (int i = 0; i <= kRings; ++i) theta_[static_cast<size_t>(i)] = kPi * std::pow(static_cast<double>(i) / kRings, 3);
  std::vector<double> mass(kRings);
  double total = 0;
  for (int i = 0; i < kRings; ++i) {
    // ∫ F 2π sin θ dθ over the ring by Simpson's rule in θ.
    const double a = theta_[static_cast<size_t>(i)], b = theta_[static_cast<size_t>(i + 1)], m = (a + b) / 2;
    auto f = [&](double t) { return phase(std::cos(t)) * 2 * kPi * std::sin(t); };
    mass[static_cast<size_t>(i)] = std::max(0.0, (b - a) / 6 * (f(a) + 4 * f(m) + f(b)));
    total += mass[static_cast<size_t>(i)];
  }
  for (int i = 0; i < kRings; ++i) {
    const double p = mass[static_cast<size_t>(i)] / total;
    cdf_[static_cast<size_t>(i + 1)] = cdf_[static_cast<size_t>(i)] + p;
    const double solid_angle =
        2 * kPi * (std::cos(theta_[static_cast<size_t>(i)]) - std::cos(theta_[static_cast<size_t>(i + 1)]));
    ring_density_[static_cast<size_t>(i)] = solid_angle > 0 ? p / solid_angle : 0.0;
  }
  cdf_.back() = 1.0;
}

PhaseSampler::Sample PhaseSampler::sample(const Vec3& forward, double u1, double u2) const {
  const auto at = std::upper_bound(cdf_.begin(), cdf_.end(), u1);
  const int i = std::clamp(static_cast<int>(at - cdf_.begin()) - 1, 0, kRings - 1);
  const double c0 = std::cos(theta_[static_cast<size_t>(i)]), c1 = std::cos(theta_[static_cast<size_t>(i + 1)]);
  const double span = cdf_[static_cast<size_t>(i + 1)] - cdf_[static_cast<size_t>(i)];
  const double t = span > 0 ? std::clamp((u1 - cdf_[static_cast<size_t>(i)]) / span, 0.0, 1.0) : 0.5;
  const double cos_theta = c0 + t * (c1 - c0), sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  const double phi = 2 * kPi * u2;
  Vec3 a, b;
  orthonormal_frame(forward, a, b);
  const Vec3 direction = normalize(sin_theta * std::cos(phi) * a + sin_theta * std::sin(phi) * b + cos_theta * forward);
  return {direction, ring_density_[static_cast<size_t>(i)]};
}

int PhaseSampler::ring_of(double cos_theta) const {
  const double theta = std::acos(std::clamp(cos_theta, -1.0, 1.0));
  return std::clamp(static_cast<int>(std::cbrt(theta / kPi) * kRings), 0, kRings - 1);
}

double PhaseSampler::pdf(double cos_theta) const { return ring_density_[static_cast<size_t>(ring_of(cos_theta))]; }

PhaseSampler::Cone PhaseSampler::cone(double max_theta) const {
  const auto edge = std::lower_bound(theta_.begin(), theta_.end(), max_theta);
  const int rings = std::clamp(static_cast<int>(edge - theta_.begin()), 1, kRings);
  return {rings, cdf_[static_cast<size_t>(rings)], std::cos(theta_[static_cast<size_t>(rings)])};
}

PhaseSampler::Sample PhaseSampler::sample_within(const Cone& cone, const Vec3& forward, double u1, double u2) const {
  // The rings' cumulative probabilities start at 0, so u1 scaled into [0, P) picks
  // among the cone's rings only (the last one's upper edge excluded).
  const double u = std::min(u1 * cone.probability, std::nextafter(cone.probability, 0.0));
  Sample s = sample(forward, u, u2);
  s.pdf /= cone.probability;
  return s;
}

double PhaseSampler::pdf_within(const Cone& cone, double cos_theta) const {
  const int ring = ring_of(cos_theta);
  return ring < cone.rings ? ring_density_[static_cast<size_t>(ring)] / cone.probability : 0.0;
}

}  // namespace skylit
