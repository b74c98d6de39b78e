// The sky dome (and the ground's half of the sphere) divided into band sources, after
// the paper's §4 (Eqs. 3–7) and Nishita & Nakamae (1986).
//
// Each band is a slice of the sphere between two planes through the x axis (east–west):
// its sample plane is tilted by δ from the horizontal, and a sky element on its sample
// line is found by the angle α from the x axis: ω(α, δ) = (cos α, sin α cos δ, sin α sin δ).
// δ from 0 to π sweeps the sky (z ≥ 0) from the northern horizon over the zenith to the
// southern one; δ from π to 2π sweeps the ground's half. The solid angle of an element is
// sin α dα dδ.
//
// As in the paper, bands are spaced so that cos(δ_l − Δ_l) − cos(δ_l + Δ_l) is the same
// for every band of the sky: each band then carries the same weight for a horizontal
// surface (the paper writes 1/N for this constant over its quarter-sphere of tilts; over
// the whole dome, δ ∈ [0, π], the constants add up to 2, so here each is 2/N). The
// elements along a band are spaced so that each has the same solid angle.
#pragma once

#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

struct SkyElement {
  Vec3 direction;      // unit, world frame (x east, y north, z up)
  double solid_angle;  // sr
  int band;            // 0 … 2N − 1; bands N … 2N − 1 look down
  int segment;         // 0 … M − 1 along the band
};

// `count` directions spread evenly over the sphere (a spherical Fibonacci lattice,
// González 2010), each standing for 4π/count sr: a quadrature whose points do not line
// up with straight edges the way a latitude–longitude grid's do.
std::vector<SkyElement> fibonacci_sphere(int count);

class BandSources {
 public:
  // `bands` per half sphere (N) and `segments` per band (M).
  BandSources(int bands, int segments);

  int bands() const { return bands_; }
  int segments() const { return segments_; }
  const std::vector<SkyElement>& elements() const { return elements_; }

  // Tilt of band l's sample plane and its half-width Δ_l (radians).
  double tilt(int band) const { return tilt_[static_cast<size_t>(band)]; }
  double half_width(int band) const { return half_width_[static_cast<size_t>(band)]; }
  // α of segment j's centre along any band.
  double alpha(int segment) const { return alpha_[static_cast<size_t>(segment)]; }
  const SkyElement& element(int band, int segment) const {
    return elements_[static_cast<size_t>(band * segments_ + segment)];
  }
  // The band and segment whose element contains `direction`.
  void locate(const Vec3& direction, int& band, int& segment) const;

 private:
  int bands_, segments_;
  std::vector<double> tilt_, half_width_, tilt_edges_, alpha_, alpha_edges_;
  std::vector<SkyElement> elements_;
};

}  // namespace skylit
