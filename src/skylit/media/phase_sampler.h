// Drawing scattering directions in proportion to a phase function, for the path-traced
// reference: any phase function of cos θ (the fog's droplet fit with its sharp forward
// peak, Henyey–Greenstein, the air's), from a table of its probability over rings of
// scattering angle θ, graded toward θ = 0 where droplet phase functions put a
// diffraction peak a fraction of a degree wide. Inside a ring the direction is uniform
// in solid angle; the density stated is the table's, and the caller weighs by the true
// phase function over it, so the table's coarseness costs noise, never bias.
#pragma once

#include <functional>
#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

class PhaseSampler {
 public:
  static constexpr int kRings = 4096;

  // `phase(cos θ)`, sr⁻¹, normalised to 1 over the sphere.
  explicit PhaseSampler(const std::function<double(double cos_theta)>& phase);

  struct Sample {
    Vec3 direction;  // unit
    double pdf;      // sr⁻¹
  };
  // A direction whose cosine with `forward` (unit) follows the phase function.
  Sample sample(const Vec3& forward, double u1, double u2) const;
  // The density of a direction at cos θ from forward, sr⁻¹.
  double pdf(double cos_theta) const;

  // Drawing only within the rings that reach out to `max_theta` (the forward cone the
  // path tracer's sun strategy draws from): the same rings, the density divided by their
  // probability, 0 beyond them.
  struct Cone {
    int rings;           // the rings [0, rings)
    double probability;  // of those rings
    double min_cos;      // cos of the outer edge of the last ring
  };
  Cone cone(double max_theta) const;
  Sample sample_within(const Cone& cone, const Vec3& forward, double u1, double u2) const;
  double pdf_within(const Cone& cone, double cos_theta) const;

 private:
  std::vector<double> theta_;         // kRings + 1 ring edges, from 0 to π
  std::vector<double> cdf_;           // kRings + 1
  std::vector<double> ring_density_;  // sr⁻¹ in each ring
  int ring_of(double cos_theta) const;
};

}  // namespace skylit
