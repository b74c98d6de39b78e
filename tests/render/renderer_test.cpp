// The foundation's light: the extraterrestrial sun as a directional light, Lambertian
// surfaces, hard shadows and the uniform placeholder sky. Pixel luminances are checked
// against the same quantities computed independently at 1 nm from the data tables.
#include "skylit/render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/geometry/primitives.h"
#include "skylit/render/placeholder_sky.h"
#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/illuminants.h"

namespace skylit {
namespace {

// 683 lm/W × ∫ E(λ) ȳ(λ) dλ over 360–830 nm at 1 nm: the extraterrestrial solar
// illuminance, about 133 klx (Gueymard 2004's spectrum).
double solar_illuminance_1nm() {
  const Tabulated& sun = solar_extraterrestrial_table();
  const Tabulated& y = cie1931().y;
  double sum = 0;
  for (int nm = 360; nm <= 830; ++nm) sum += sun(nm) * y(nm);
  return kMaxLuminousEfficacy * sum;
}

Scene open_plane_scene(double sun_altitude_deg, float reflectance) {
  Scene scene;
  scene.camera = Camera{{0, 0, 10}, {0, 0.001, 0}, {0, 1, 0}, 20.0};  // looking straight down
  scene.sun = Sun{sun_altitude_deg, 200};
  scene.materials.push_back({"white", DiffuseMaterial{Spectrum(reflectance)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 1000), 0});
  scene.render = RenderSettings{8, 8, std::nullopt, 1};
  return scene;
}

TEST(Renderer, ExtraterrestrialIlluminanceIsThePublishedValue) {
  // The solar illuminance constant is about 133 klx at 1366 W/m² (Darula, Kittler &
  // Gueymard 2005, Leukos 1(3)); the ±1.5 klx band catches unit and scale mistakes.
  EXPECT_NEAR(solar_illuminance_1nm(), 133.3e3, 1.5e3);
}

TEST(Renderer, HorizontalPlaneHasLambertLuminance) {
  // L = ρ (E_sun sin(a) + π L_sky) / π with both illuminances from 1 nm integration.
  // Binning the sun's spectrum into kSpectralBins bins changes the illuminance by less
  // than 0.3 % (the bin-count study); allow 0.5 %.
  for (double altitude : {10.0, 35.0, 70.0}) {
    const Scene scene = open_plane_scene(altitude, 0.6f);
    const Renderer renderer(scene);
    const XyzImage image = renderer.render();
    const double expected =
        0.6 * (solar_illuminance_1nm() * std::sin(radians(altitude)) + kPi * kPlaceholderSkyLuminance) / kPi;
    for (int y = 0; y < 8; y += 7)
      for (int x = 0; x < 8; x += 7) EXPECT_NEAR(image.at(x, y).y, expected, 0.005 * expected) << altitude;
  }
}

TEST(Renderer, SunBelowHorizonLeavesOnlySkyLight) {
  const Scene scene = open_plane_scene(-5.0, 1.0f);
  const XyzImage image = Renderer(scene).render();
  EXPECT_NEAR(image.at(4, 4).y, kPlaceholderSkyLuminance, 1e-3 * kPlaceholderSkyLuminance);
}

TEST(Renderer, BoxCastsAHardShadowWhereGeometrySays) {
  // Sun due south at 45°: a 10 m high box standing on [-5,5]² shades the ground up to
  // y = 5 + 10/tan(45°) = 15 m north of its centre.
  Scene scene = open_plane_scene(45.0, 0.5f);
  scene.sun.azimuth_deg = 180;
  scene.objects.push_back({"box", make_box({-5, -5, 0}, {5, 5, 10}), 0});
  const Renderer renderer(scene);
  uint64_t rays = 0;
  auto ground_luminance = [&](double y) {
    const Ray down{{0.0, y, 50.0}, {0, 0, -1}};
    return luminance(renderer.radiance(down, rays));
  };
  const double sky_only = 0.5 * kPlaceholderSkyLuminance;
  const double lit = 0.5 * (solar_illuminance_1nm() * std::sin(radians(45.0)) + kPi * kPlaceholderSkyLuminance) / kPi;
  EXPECT_NEAR(ground_luminance(10.0), sky_only, 0.01 * sky_only);   // in the shadow
  EXPECT_NEAR(ground_luminance(14.5), sky_only, 0.01 * sky_only);   // just inside its edge
  EXPECT_NEAR(ground_luminance(15.5), lit, 0.01 * lit);             // just outside
  EXPECT_NEAR(ground_luminance(-10.0), lit, 0.01 * lit);            // on the sunny side
  EXPECT_GT(rays, 0u);
}

TEST(Renderer, SkyPixelsShowThePlaceholderSky) {
  Scene scene = open_plane_scene(30.0, 0.5f);
  scene.camera = Camera{{0, 0, 10}, {0, 0, 20}, {0, 1, 0}, 20.0};  // looking straight up
  const XyzImage image = Renderer(scene).render();
  EXPECT_NEAR(image.at(3, 3).y, kPlaceholderSkyLuminance, 1e-3 * kPlaceholderSkyLuminance);
  // D65 chromaticity (x, y) = (0.3127, 0.3290).
  const Xyz c = image.at(3, 3);
  EXPECT_NEAR(c.x / (c.x + c.y + c.z), 0.3127, 2e-3);
  EXPECT_NEAR(c.y / (c.x + c.y + c.z), 0.3290, 2e-3);
}

}  // namespace
}  // namespace skylit
