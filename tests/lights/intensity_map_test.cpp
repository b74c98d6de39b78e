// The octahedral intensity map (lights/intensity_map.h) against the exact look-up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "skylit/lights/ies_reader.h"
#include "skylit/lights/intensity_map.h"

namespace skylit {
namespace {

struct Deviation {
  double worst, p999;  // relative to the distribution's peak
};

// Over 200,000 random directions: the deviation from Luminaire::intensity, largest and
// 99.9th percentile.
Deviation deviation(const Luminaire& luminaire) {
  const IntensityMap map(luminaire);
  std::mt19937 rng(3);
  std::normal_distribution<double> gauss;
  std::vector<double> e;
  for (int i = 0; i < 200000; ++i) {
    const Vec3 d{gauss(rng), gauss(rng), gauss(rng)};
    e.push_back(std::abs(map.candela(d) - luminaire.intensity(d)) / luminaire.distribution().peak_candela());
  }
  std::sort(e.begin(), e.end());
  return {e.back(), e[e.size() * 999 / 1000]};
}

TEST(IntensityMap, RoadLuminaireWithinAFewTenthsOfAPercentOfPeak) {
  // The example's road luminaire (5° γ steps, 15° C steps, a cut-off at 88°), tilted
  // and turned: bilinear resampling at ~0.35° texels stays within 0.3 % of the peak in
  // 999 directions of 1000; the worst, 1.1 %, where the cut-off bends the table.
  const IesPhotometry ies = read_ies(std::string(SKYLIT_SOURCE_DIR) + "/examples/lamps/road_luminaire.ies");
  const Luminaire luminaire({1, 2, 8}, ies.distribution, normalize(Vec3{0.1, -0.2, -1}), 37);
  const Deviation d = deviation(luminaire);
  EXPECT_LT(d.worst, 0.015);  // measured 0.011, at the cut-off's kink
  EXPECT_LT(d.p999, 0.003);   // measured 0.0021
}

TEST(IntensityMap, SoftSpotWithinOnePercentAndIsotropicExact) {
  const Luminaire spot({0, 0, 1}, IntensityDistribution::spot(20000, 4, 13), normalize(Vec3{0, -1, -0.03}));
  EXPECT_LT(deviation(spot).worst, 0.01);
  const Luminaire bulb({0, 0, 1}, IntensityDistribution::isotropic(100));
  EXPECT_EQ(deviation(bulb).worst, 0.0);
}

}  // namespace
}  // namespace skylit
