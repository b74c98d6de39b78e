// The path-traced reference's luminance along one ray, with its standard error: the
// mean of `paths` independent paths (render/path_integrator.h), for tests that compare
// the fast method with it at a point.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "skylit/render/path_integrator.h"
#include "skylit/spectrum/cie.h"

namespace skylit::testing {

struct Estimate {
  double mean, standard_error;
};

inline Estimate path_luminance(const PathIntegrator& path, const Ray& ray, int paths, uint64_t seed) {
  double sum = 0, squares = 0;
  for (int k = 0; k < paths; ++k) {
    CounterRandom random(seed, 0, static_cast<uint64_t>(k));
    const double v = luminance(path.sample(ray, random));
    sum += v;
    squares += v * v;
  }
  const double mean = sum / paths;
  return {mean, std::sqrt(std::max(0.0, squares / paths - mean * mean) / (paths - 1))};
}

}  // namespace skylit::testing
