// The renderer's light: the sun through the air with hard shadows, the unobstructed sky
// on Lambertian surfaces, the sky and sun where no object is seen, and aerial
// perspective. Pixel luminances are checked against the atmosphere model's own
// illuminances, computed independently of the image.
#include "skylit/render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/atmosphere/solar_spectrum.h"
#include "skylit/geometry/primitives.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

Scene open_plane_scene(double sun_altitude_deg, float reflectance) {
  Scene scene;
  scene.camera = Camera{{0, 0, 10}, {0, 0.001, 0}, {0, 1, 0}, 20.0};  // looking straight down
  scene.sun = Sun{sun_altitude_deg, 200};
  scene.materials.push_back({"white", DiffuseMaterial{Spectrum(reflectance)}});
  scene.materials.push_back({"black", DiffuseMaterial{Spectrum(0.0f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 1000), 0});
  scene.render = RenderSettings{8, 8, std::nullopt, 1};
  return scene;
}

TEST(Renderer, HorizontalPlaneHasLambertLuminance) {
  // L = ρ (E_direct sin a + E_sky) / π with both illuminances from the atmosphere
  // model; 10 m of air between camera and plane change it by well under 0.1 %: 0.5 %.
  for (double altitude : {10.0, 35.0, 70.0}) {
    const Scene scene = open_plane_scene(altitude, 0.6f);
    const Renderer renderer(scene);
    const XyzImage image = renderer.render();
    const double e_direct = illuminance(renderer.sky().direct_sun(0.0)) * std::sin(radians(altitude));
    const double e_sky = illuminance(renderer.sky().sky_irradiance({0, 0, 1}));
    const double expected = 0.6 * (e_direct + e_sky) / kPi;
    for (int y = 0; y < 8; y += 7)
      for (int x = 0; x < 8; x += 7) EXPECT_NEAR(image.at(x, y).y, expected, 0.005 * expected) << altitude;
    // A clear sky: the sun dominates on a horizontal plane once it is well up. At 10° the
    // two are comparable (the beam's horizontal share is sin 10° = 0.17 of its normal
    // illuminance; with converged multiple scattering the diffuse is 1.05 times it).
    if (altitude >= 30) {
      EXPECT_GT(e_direct, e_sky);
    }
  }
}

TEST(Renderer, SunBelowHorizonLeavesOnlySkyLight) {
  const Scene scene = open_plane_scene(-3.0, 1.0f);
  const Renderer renderer(scene);
  const double sky_only = illuminance(renderer.sky().sky_irradiance({0, 0, 1})) / kPi;
  EXPECT_GT(sky_only, 1.0);  // civil twilight still lights the ground
  EXPECT_NEAR(renderer.render().at(4, 4).y, sky_only, 0.005 * sky_only);
}

TEST(Renderer, BoxCastsAHardShadowWhereGeometrySays) {
  // Sun due south at 45°: a 10 m high box standing on [-5,5]² shades the ground up to
  // y = 5 + 10/tan(45°) = 15 m north of its centre.
  Scene scene = open_plane_scene(45.0, 0.5f);
  scene.sun.azimuth_deg = 180;
  scene.objects.push_back({"box", make_box({-5, -5, 0}, {5, 5, 10}), 0});
  const Renderer renderer(scene);
  auto ground_luminance = [&](double y) {
    const Ray down{{0.0, y, 50.0}, {0, 0, -1}};
    return luminance(renderer.radiance(down));
  };
  // The sky's share, obstructed by the box near it, from the sky light itself; the
  // sun's share is all or nothing.
  // Seen through the camera's 50 m of air.
  const MediumStretch air = renderer.sky().aerial_perspective({0, 0, -1}, 50.0);
  // The ground (albedo 0.5) under irradiance E, seen through the air.
  auto seen = [&](const Irradiance& e) {
    return luminance(air.seen_through(lambertian_radiance(Reflectance(0.5f), e)));
  };
  auto sky_only = [&](double y) { return seen(renderer.sky_light().diffuse_irradiance({0, y, 0}, {0, 0, 1})); };
  auto sky_and_sun = [&](double y) {
    return seen(renderer.sky_light().diffuse_irradiance({0, y, 0}, {0, 0, 1}) +
                renderer.sky().direct_sun(0.0) * static_cast<float>(std::sin(radians(45.0))));
  };
  // 0.5 %: what is left is float rounding and the sun's profile against height.
  EXPECT_NEAR(ground_luminance(10.0), sky_only(10.0), 0.005 * sky_only(10.0));           // in the shadow
  EXPECT_NEAR(ground_luminance(14.5), sky_only(14.5), 0.005 * sky_only(14.5));           // just inside its edge
  EXPECT_NEAR(ground_luminance(15.5), sky_and_sun(15.5), 0.005 * sky_and_sun(15.5));     // just outside
  EXPECT_NEAR(ground_luminance(-10.0), sky_and_sun(-10.0), 0.005 * sky_and_sun(-10.0));  // sunny side
  // Near the box the ground sees less sky than in the open.
  EXPECT_LT(illuminance(renderer.sky_light().diffuse_irradiance({0, 10, 0}, {0, 0, 1})),
            illuminance(renderer.sky().sky_irradiance({0, 0, 1})));
  EXPECT_GT(renderer.rays_traced(), 0u);
}

TEST(Renderer, SkyPixelsShowTheSkyAndTheSun) {
  Scene scene = open_plane_scene(60.0, 0.5f);
  scene.camera = Camera{{0, 0, 10}, {0, 0, 20}, {0, 1, 0}, 20.0};  // looking straight up
  scene.render = RenderSettings{1, 1, std::nullopt, 1};            // one sample, at the zenith
  const Renderer renderer(scene);
  const XyzImage image = renderer.render();
  const Vec3 up{0, 0, 1};
  const double zenith = luminance(renderer.sky().sky_radiance(up));
  EXPECT_NEAR(image.at(0, 0).y, zenith, 1e-4 * zenith);
  // The sun's disc: looking at it, luminance of order 1e9 cd/m² (1.6e9 at noon).
  const double sun = luminance(renderer.radiance(Ray{{0, 0, 10}, renderer.sky().to_sun()}));
  EXPECT_GT(sun, 3e8);
  EXPECT_LT(sun, 3e9);
}

TEST(Renderer, DistantObjectsAreSeenThroughTheAir) {
  // A black wall adds no light of its own: what the camera sees of it is the air in
  // between, more of it the farther the wall.
  Scene scene = open_plane_scene(30.0, 0.5f);
  scene.camera = Camera{{0, 0, 2}, {0, 100, 2}, {0, 0, 1}, 20.0};
  scene.objects.push_back({"near wall", make_box({-50, 50, 0}, {-1, 60, 40}), 1});
  scene.objects.push_back({"far wall", make_box({1, 5000, 0}, {3000, 5100, 4000}), 1});
  const Renderer renderer(scene);
  const double near = luminance(renderer.radiance(Ray{{0, 0, 2}, normalize(Vec3{-0.2, 1, 0.1})}));
  const double far = luminance(renderer.radiance(Ray{{0, 0, 2}, normalize(Vec3{0.2, 1, 0.05})}));
  const double horizon = luminance(renderer.sky().sky_radiance(normalize(Vec3{0.2, 1, 0.0})));
  EXPECT_GT(near, 0.0);
  EXPECT_GT(far, 10 * near);
  EXPECT_LT(far, horizon);  // 5 km of air is not yet the whole horizon's
}

}  // namespace
}  // namespace skylit

namespace skylit {
namespace {

TEST(Renderer, WhitePlaneMatchesTheSpectrumCommandsIlluminances) {
  // The check: a horizontal white surface in the open has luminance
  // ρ (E_direct + E_sky)/π with both illuminances from `skylit spectrum` (the model
  // integrated directly at 1 nm, not through the renderer's tables and bins). The two
  // paths differ by the tables' interpolation and 40-bin colorimetry: 1.5 %.
  const double altitude = 35.0;
  const Scene scene = open_plane_scene(altitude, 1.0f);
  const XyzImage image = Renderer(scene).render();
  const auto samples = solar_spectrum(AtmosphereSettings{}, direction_from_altitude_azimuth(altitude, 200), 10.0);
  const ColourMatchingFunctions& cmf = cie1931();
  double e_direct = 0, e_sky = 0;
  for (const SolarSpectrumSample& s : samples) {
    e_direct += kMaxLuminousEfficacy * s.direct_normal * cmf.y(s.wavelength_nm) * std::sin(radians(altitude));
    e_sky += kMaxLuminousEfficacy * s.diffuse_horizontal * cmf.y(s.wavelength_nm);
  }
  const double expected = (e_direct + e_sky) / kPi;
  EXPECT_NEAR(image.at(4, 4).y, expected, 0.015 * expected);
}

}  // namespace
}  // namespace skylit
