// The clear air in the scene's shadows (render/shadowed_air.h): a view through a
// building's shadow loses the sunbeam's single scattering over the shadowed stretch, and
// keeps it elsewhere. Checked on a black wall 50 m away (its luminance is the air's
// alone) under a roof plate whose shadow covers the view wholly, in part, or not at all,
// and the stretch's single scattering against an integrator that has nothing else.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../test_support.h"
#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/scattering_integrator.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// The sun's single scattering over [0, d] by ScatteringIntegrator::sun_single_scattering
// against the light an integrator without multiple scattering or ground gathers to the
// same distance (up_to in 128 segments): the same physics by separate quadratures,
// within 0.5 % in every bin (measured: 0.03 % at worst, a view rising 17° over 3 km).
TEST(ShadowedAir, TheStretchsSingleScatteringIsWhatASingleScatteringIntegratorGathers) {
  const Atmosphere atmosphere{AtmosphereSettings{}};
  const ScatteringIntegrator single(atmosphere.medium(), atmosphere.transmittance(), nullptr, nullptr,
                                    AtmosphereSettings{}.aerosol, 0.0);
  const double r = atmosphere.ground_radius() + 1.6, mu_sun = 0.5;
  for (const double mu : {0.0, 0.3, -0.01})
    for (const double nu : {0.9, 0.0, -0.6})
      for (const double d : {10.0, 100.0, 1000.0, 3000.0}) {
        SCOPED_TRACE(::testing::Message() << "mu " << mu << " nu " << nu << " d " << d);
        std::vector<double> stops;  // 128 midpoint segments: converged to 1e-4
        for (int k = 1; k <= 64; ++k) stops.push_back(d * k / 64);
        const Spectrum expected = single.up_to(r, mu, mu_sun, nu, stops).back().radiance;
        const Spectrum whole = atmosphere.integrator().sun_single_scattering(r, mu, mu_sun, nu, 0, d, 250);
        // And in two stretches, the far one dimmed by the near one.
        const Spectrum near = atmosphere.integrator().sun_single_scattering(r, mu, mu_sun, nu, 0, 0.4 * d, 250);
        const Spectrum far = atmosphere.integrator().sun_single_scattering(r, mu, mu_sun, nu, 0.4 * d, d, 250);
        for (int k = 0; k < kSpectralBins; ++k) {
          EXPECT_NEAR(whole[k], expected[k], 5e-3 * expected[k]) << "bin " << k;
          EXPECT_NEAR(near[k] + far[k], expected[k], 5e-3 * expected[k]) << "bin " << k;
        }
      }
}

// Camera 1.6 m up looking level south at a black wall 50 m away; the sun 30° up in the
// north, behind the camera, so that the wall's own shadow falls behind it. A roof plate
// 10 m up between y0 and y1 shades the view's height 1.6 m between y0 − 14.55 and
// y1 − 14.55 (the plate's shadow moves (10 − 1.6)/tan 30° south).
std::string scene(const std::string& model, double y0, double y1) {
  std::string roof;
  if (y1 > y0)
    roof = R"({"type": "box", "material": "black", "min": [-40, )" + std::to_string(y0) + R"(, 10], "max": [40, )" +
           std::to_string(y1) + R"(, 10.2]}, )";
  return R"({"camera": {"position": [0, 0, 1.6], "look_at": [0, -50, 1.6], "vertical_fov_deg": 10},
    "sun": {"altitude_deg": 30, "azimuth_deg": 0}, "atmosphere": {"model": ")" +
         model + R"("}, "materials": {"black": {"type": "diffuse", "reflectance": 0}},
    "objects": [)" +
         roof +
         R"({"type": "box", "material": "black", "min": [-20, -51, 0], "max": [20, -50, 8]}],
    "render": {"width": 32, "height": 18}})";
}

// The wall's luminance straight ahead: the air's light alone.
double wall_luminance(const std::string& text) {
  testing::TempDir dir;
  const Scene loaded = load_scene(dir.write("s.json", text));
  const Renderer renderer(loaded);
  return luminance(renderer.radiance(Ray{{0, 0, 1.6}, {0, -1, 0}}).spectrum());
}

TEST(ShadowedAir, AViewInABuildingsShadowLosesTheSunbeamsScatteringThere) {
  // The paper's model has single scattering only: in a whole shadow nothing is left,
  // and a shadow over 20 of the 50 m takes 20/50 of it (the air is uniform along a level
  // view; its transmittance over 50 m, 0.99, tilts the share by under 1 %).
  const double open = wall_luminance(scene("paper", 0, 0));
  ASSERT_GT(open, 1.0);
  EXPECT_LT(wall_luminance(scene("paper", -100, 40)), 1e-3 * open);
  const double part = wall_luminance(scene("paper", -30 + 14.55, -10 + 14.55));
  EXPECT_NEAR(part / open, 0.6, 0.01);
  // The full model keeps what the shadowed air scatters of the sky's light (the
  // multiple scattering: a quarter to a half of the air's light in this view).
  const double full_open = wall_luminance(scene("full", 0, 0));
  const double full_shaded = wall_luminance(scene("full", -100, 40));
  EXPECT_GT(full_shaded, 0.2 * full_open);
  EXPECT_LT(full_shaded, 0.8 * full_open);
}

}  // namespace
}  // namespace skylit
