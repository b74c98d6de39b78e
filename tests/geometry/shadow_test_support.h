// Shared by the shadow-volume tests: an independent check of lit intervals by sampling.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "skylit/geometry/intervals.h"

namespace skylit {

// Samples [0, t_max] at kSamples midpoints with an independent test of light (an
// occlusion ray): how many samples it finds lit, and how many disagree with `lit`
// farther than 1 mm from an interval's end (the samples' own resolution is coarser).
struct SampledLight {
  int lit_samples = 0, disagreements = 0;
};
template <class IsLit>
SampledLight sample_light(const std::vector<Interval>& lit, double t_max, int samples, const IsLit& is_lit) {
  SampledLight out;
  const double step = t_max / samples;
  for (int k = 0; k < samples; ++k) {
    const double t = (k + 0.5) * step;
    const bool traced_lit = is_lit(t);
    out.lit_samples += traced_lit;
    bool exact_lit = false;
    double distance = std::numeric_limits<double>::infinity();
    for (const Interval& i : lit) {
      exact_lit |= i.begin <= t && t <= i.end;
      distance = std::min({distance, std::abs(t - i.begin), std::abs(t - i.end)});
    }
    if (exact_lit != traced_lit && distance > 1e-3) ++out.disagreements;
  }
  return out;
}

}  // namespace skylit
