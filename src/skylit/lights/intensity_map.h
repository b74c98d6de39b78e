// A luminaire's intensity resampled on an octahedral map of directions (Engelhardt &
// Dachsbacher 2008, "Octahedron environment maps"), for the renderer's many look-ups:
// a direction becomes a map position with a few additions and one division, where the
// exact look-up (Luminaire::intensity) needs an arc cosine, an arc tangent and two
// interpolations in the photometric table.
//
// The map's centre is the luminaire's nadir (γ = 0), its inner diamond the lower
// hemisphere (γ ≤ 90°, where street lamps and headlights send their light), the corners
// the upper one; the values at texel centres are exact, bilinear between. Measured
// deviation from the exact look-up: docs/lights.md and tests/lights/intensity_map_test.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/lights/luminaire.h"

namespace skylit {

class IntensityMap {
 public:
  static constexpr int kDefaultResolution = 512;
  explicit IntensityMap(const Luminaire& luminaire, int resolution = kDefaultResolution);

  // Candela toward a world direction (any non-zero length).
  double candela(const Vec3& world_direction) const;

 private:
  Vec3 c0_, c90_, nadir_;
  int n_;
  double half_n_;
  bool constant_;  // isotropic: no map needed
  double constant_value_;
  // Texels as fractions of the largest, in 16 bits (steps of 1.5e-5 of the peak): half
  // the memory of floats, so more of the maps stay in cache.
  std::vector<uint16_t> texels_;
  double scale_;  // candela per texel unit
};

}  // namespace skylit
