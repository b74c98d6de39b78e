// The delta-Eddington slab (clouds/cloud_two_stream.h) against the published closed form
// of its albedo and against the energy it must conserve.
#include <gtest/gtest.h>

#include <cmath>

#include "skylit/clouds/cloud_two_stream.h"
#include "skylit/core/angles.h"

namespace skylit {
namespace {

TEST(CloudTwoStream, SunAlbedoIsMeadorAndWeaversConservativeResult) {
  // Meador & Weaver (1980), ω = 1: R = [γ1 τ + (γ3 − γ1 μ0)(1 − e^{−τ/μ0})] / (1 + γ1 τ) with
  // the Eddington γ1 = 3(1 − g)/4, γ3 = (2 − 3 g μ0)/4: the same slab solved another way,
  // so agreement to rounding (1e-12).
  for (double g : {0.0, 0.47, 0.8})
    for (double tau : {0.1, 1.0, 4.5, 11.0})
      for (double mu0 : {0.1, 0.5, 0.866, 1.0}) {
        const double g1 = 0.75 * (1 - g), g3 = 0.25 * (2 - 3 * g * mu0);
        const double expected = (g1 * tau + (g3 - g1 * mu0) * -std::expm1(-tau / mu0)) / (1 + g1 * tau);
        EXPECT_NEAR(eddington_sun_albedo(tau, g, mu0), expected, 1e-12) << g << ' ' << tau << ' ' << mu0;
      }
  // Thick slabs reflect nearly all, and more of a low sun than of a high one.
  const DeltaScaling droplets(0.879);
  EXPECT_GT(eddington_sun_albedo(droplets.scaled_depth(1000), droplets.asymmetry, 0.5), 0.98);
  EXPECT_GT(eddington_sun_albedo(droplets.scaled_depth(20), droplets.asymmetry, 0.5),
            eddington_sun_albedo(droplets.scaled_depth(20), droplets.asymmetry, 0.866));
}

TEST(CloudTwoStream, FluxesBalance) {
  // No absorption: what leaves the top and the bottom (diffuse and direct) is what came
  // in, μ0 for the sun, 1 for a diffuse irradiance on either face (to 1e-12).
  const double g = 0.47;
  for (double tau : {0.2, 3.0, 12.0})
    for (double mu0 : {0.2, 0.7}) {
      const EddingtonField top = eddington_sun_field(tau, g, mu0, 0), bottom = eddington_sun_field(tau, g, mu0, tau);
      const double up = kPi * (top.mean - 2.0 / 3.0 * top.flux), down = kPi * (bottom.mean + 2.0 / 3.0 * bottom.flux);
      EXPECT_NEAR(up + down + mu0 * std::exp(-tau / mu0), mu0, 1e-12);
      for (bool from_top : {true, false}) {
        const EddingtonField a = eddington_diffuse_field(tau, g, 0, from_top);
        const EddingtonField b = eddington_diffuse_field(tau, g, tau, from_top);
        EXPECT_NEAR(kPi * (a.mean - 2.0 / 3.0 * a.flux) + kPi * (b.mean + 2.0 / 3.0 * b.flux), 1.0, 1e-12);
        // The light comes in where it should: π(I0 ± 2/3 I1) on the lit face is 1.
        const EddingtonField lit = from_top ? a : b;
        EXPECT_NEAR(kPi * (lit.mean + (from_top ? 2.0 : -2.0) / 3.0 * lit.flux), 1.0, 1e-12);
      }
    }
}

}  // namespace
}  // namespace skylit
