// Clouds in rendered scenes: a cloud's edge is brighter than its centre with the sun
// behind it, its sunlit side brighter with the sun behind the camera, and its shadow
// lands on the ground where the geometry says.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skylit/geometry/primitives.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

Scene cloud_scene(double sun_azimuth_deg) {
  Scene scene;
  scene.camera = Camera{{0, 0, 2}, {0, 0, 100}, {0, 1, 0}, 60.0};  // looking straight up
  scene.sun = Sun{35, sun_azimuth_deg};
  scene.materials.push_back({"ground", DiffuseMaterial{Spectrum(0.2f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 20000), 0});
  CloudShape c;
  c.center_x = 0;
  c.center_y = 0;
  c.altitude = 1000;
  c.semi_axis_a = 500;
  c.semi_axis_b = 500;
  c.max_thickness = 300;  // no texture: a smooth lens, thickest at the centre
  scene.clouds.push_back(c);
  scene.render = RenderSettings{8, 8, std::nullopt, 1};
  return scene;
}

double luminance_toward(const Renderer& renderer, const Vec3& target) {
  return luminance(renderer.radiance(Ray{{0, 0, 2}, normalize(target - Vec3{0, 0, 2})}));
}

TEST(CloudRender, EdgeOutshinesCentreWithTheSunBehindTheCloud) {
  // The camera under the cloud's centre looks up; the sun (35°) is beyond the cloud's
  // north edge, so light scattered forward through the thin edge reaches the camera.
  // The fast method gives edge/centre 3.0, the path-traced reference about 2.3 (256,000
  // paths per ray: edge 40.8 ± 2.1, centre 17.7 ± 3.9 kcd/m²).
  const Scene scene = cloud_scene(0.0);
  const Renderer renderer(scene);
  const double centre = luminance_toward(renderer, {0, 0, 1000});
  const double north_edge = luminance_toward(renderer, {0, 480, 1000});
  EXPECT_GT(north_edge, 1.5 * centre) << north_edge << " vs " << centre;
}

TEST(CloudRender, SunlitSideIsBrighterWithTheSunBehindTheCamera) {
  // The camera far south of the cloud, the sun behind it in the south: the cloud's
  // south side faces the sun.
  Scene scene = cloud_scene(180.0);
  scene.camera = Camera{{0, -3000, 2}, {0, 0, 1000}, {0, 0, 1}, 40.0};
  const Renderer renderer(scene);
  const Vec3 eye{0, -3000, 2};
  const double south = luminance(renderer.radiance(Ray{eye, normalize(Vec3{0, -400, 1000} - eye)}));
  const double north = luminance(renderer.radiance(Ray{eye, normalize(Vec3{0, 400, 1000} - eye)}));
  EXPECT_GT(south, north);
}

TEST(CloudRender, ShadowLandsWhereTheGeometrySays) {
  // Sun at 35° from due south: the cloud (1000 m up) shades the ground 1000/tan 35° =
  // 1428 m north of its centre, a disc of radius 500 m around (0, 1428).
  const Scene scene = cloud_scene(180.0);
  const Renderer renderer(scene);
  auto ground = [&](double y) { return luminance(renderer.radiance(Ray{{0, y, 50}, {0, 0, -1}})); };
  const double shade = 1000 / std::tan(radians(35.0));
  EXPECT_LT(ground(shade), 0.5 * ground(shade - 800));  // in the shadow vs in the sun
  EXPECT_LT(ground(shade), 0.5 * ground(shade + 800));
  EXPECT_GT(ground(-200), 0.9 * ground(shade + 800));  // under the cloud itself: sunlit
}

TEST(CloudRender, DistantCloudFadesIntoHazeThroughTheAirBeforeIt) {
  // A cloud 30 km away, 2 km up (4° above the horizon). In thick haze (aerosol optical
  // depth 2: the air before the cloud has a transmittance of 1e-11) the light the
  // cloud scatters is lost on the way, and what the camera sees there is the haze's own
  // light up to the cloud (the aerial perspective A): within 2 %. In clear air the
  // cloud differs from that air light by far more. Without the air between camera and
  // cloud, the hazy cloud would show its own light undimmed. (Compared with A rather
  // than with the sky beside the cloud: the sky-view and aerial-perspective tables
  // differ by up to ~10 % on such long hazy paths, docs/atmosphere.md.)
  auto departure_from_air_light = [](double aod) {
    Scene scene = cloud_scene(90.0);  // the sun in the east, to the side
    const Vec3 eye{0, 0, 2}, target{0, 30000, 2000};
    scene.camera = Camera{eye, target, {0, 0, 1}, 20.0};
    scene.clouds[0].center_y = 30000;
    scene.clouds[0].altitude = 2000;
    scene.atmosphere.aerosol.aod_550 = aod;
    const Renderer renderer(scene);
    const Vec3 d = normalize(target - eye);
    const double entry = 29500;  // the cloud's near rim, 500 m before its centre
    const double air = luminance(renderer.sky().aerial_perspective(d, entry).in_scattered);
    return std::abs(luminance_toward(renderer, target) - air) / air;
  };
  EXPECT_LT(departure_from_air_light(2.0), 0.02);
  EXPECT_GT(departure_from_air_light(0.05), 0.2);
}

TEST(CloudRender, BaseIsDarkerThanTheSkyAtLowSun) {
  // Under a wide cloud of optical depth 25 with the sun 8° high, its base seen straight
  // up is darker than the clear sky's mean radiance (E_sky/π) there (Fig. 10's low-sun
  // bases): little of a low sun gets through, most of it is reflected from the top. At
  // 60° the same base is far brighter than that. The path-traced reference (16,000
  // paths) found base/mean sky 0.62 ± 0.02 at 8° and 3.0 ± 0.5 at 60°; the fast method
  // gives 0.82 and 3.7.
  for (double altitude : {8.0, 60.0}) {
    Scene scene = cloud_scene(180.0);
    scene.sun = Sun{altitude, 180};
    scene.clouds[0].semi_axis_a = scene.clouds[0].semi_axis_b = 6000;
    scene.clouds[0].max_thickness = 500;
    scene.clouds[0].falloff_exponent = 0.1;  // nearly flat over the camera
    const Renderer renderer(scene);
    const double base = luminance_toward(renderer, {0, 0, 1000});
    const double mean_sky = illuminance(renderer.sky().sky_irradiance({0, 0, 1})) / kPi;
    std::printf("sun %.0f: base %.0f, mean sky %.0f cd/m2\n", altitude, base, mean_sky);
    if (altitude < 10)
      EXPECT_LT(base, 0.9 * mean_sky);
    else
      EXPECT_GT(base, 1.5 * mean_sky);
  }
}

}  // namespace
}  // namespace skylit
