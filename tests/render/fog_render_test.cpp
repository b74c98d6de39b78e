// Fog in rendered scenes: a vanishing fog changes nothing, fog never adds more light
// than its sources can give, and beams come only from the sunlit parts of a ray.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "skylit/geometry/primitives.h"
#include "skylit/media/fog_sun_integral.h"
#include "skylit/render/fog_medium.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// A committed ray tracer holding `meshes`: what a surface in the fog sees around it.
std::unique_ptr<RayTracer> tracer_of(const std::vector<const TriangleMesh*>& meshes) {
  auto tracer = std::make_unique<RayTracer>();
  for (const TriangleMesh* mesh : meshes) tracer->add_mesh(*mesh);
  tracer->commit();
  return tracer;
}

Scene street_scene() {
  Scene scene;
  scene.camera = Camera{{0, -60, 1.6}, {0, 0, 10}, {0, 0, 1}, 50.0};
  scene.sun = Sun{20, 160};
  scene.materials.push_back({"white", DiffuseMaterial{Spectrum(0.8f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 2000), 0});
  scene.objects.push_back({"block", make_box({-15, 0, 0}, {15, 20, 30}), 0});
  scene.render = RenderSettings{40, 24, std::nullopt, 1};
  return scene;
}

TEST(FogRender, VanishingFogGivesTheImageWithoutFog) {
  // The paper's single scattering to 1e-4. With multiple scattering a surface in the
  // fog is lit by the field's own quadrature of the sky (fog_surface_light.h), its
  // elements' centres, instead of the cells' means of the clear sky (sky/sky_light.h):
  // the two agree to about 6e-4 in the open (FogSurfaceLight's checks against a dense
  // quadrature) and differ where an outline crosses the low sun's aureole, by up to
  // 4.8e-3 here (52 pixels of the street's floor): the fog's light keeps the error the
  // cells take out of the clear sky's (docs/sky-light.md, "The aureole behind an
  // outline"), until the fog's directions get cells of their own. 6e-3 bounds what a
  // vanishing fog may change.
  const Scene clear = street_scene();
  const XyzImage a = Renderer(clear).render();
  for (const auto& [multiple, tolerance] : {std::pair{false, 1e-4}, std::pair{true, 6e-3}}) {
    Scene fog = street_scene();
    fog.fog = FogSettings{};
    fog.fog->density_at_ground = 1e-9;
    fog.fog->multiple_scattering = multiple;
    const XyzImage b = Renderer(fog).render();
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x)
        EXPECT_NEAR(b.at(x, y).y, a.at(x, y).y, tolerance * a.at(x, y).y) << x << "," << y << " multiple " << multiple;
  }
}

TEST(FogRender, FogAddsNoMoreLightThanItsSources) {
  // Single scattering: along a ray the fog adds at most (1 − T) times its largest
  // source, ω F(θ) E_sun + J/(4π) (white fog, b = 0, no absorption): energy is
  // redirected, never made.
  // (The paper's single scattering: with multiple scattering the sky light a droplet
  // scatters is no longer bounded by the unattenuated J/4π.)
  Scene scene = street_scene();
  scene.fog = FogSettings{};
  scene.fog->multiple_scattering = false;
  const Atmosphere atmosphere(scene.atmosphere);
  const Vec3 to_sun = direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg);
  const SkyModel sky(atmosphere, to_sun, 1.6);
  const std::vector<const TriangleMesh*> meshes{&scene.objects[0].mesh, &scene.objects[1].mesh};
  const std::unique_ptr<RayTracer> tracer = tracer_of(meshes);
  const FogMedium fog(*scene.fog, meshes, *tracer, sky, scene.camera.position);
  const FogSkyLight sky_light(fog.layer(), sky);
  const Irradiance sun = sky.direct_sun(fog.layer().top_m());
  for (const Vec3 dir : {normalize(Vec3{0, 1, 0}), normalize(Vec3{0.5, 1, 0.05}), normalize(Vec3{-1, 0.2, 0.3}),
                         normalize(Vec3{0.3, 1, -0.02})}) {
    const Ray ray{scene.camera.position, dir};
    for (double d : {10.0, 100.0, 1000.0, std::numeric_limits<double>::infinity()}) {
      const MediumStretch along = fog.along(ray, d).whole();
      const double phase = fog.layer().phase(dot(dir, to_sun));
      for (int k = 0; k < kSpectralBins; k += 7) {
        const double source = phase * sun[k] + sky_light.unattenuated()[k] / (4 * kPi);
        EXPECT_LE(along.in_scattered[k], (1.0 - along.transmittance[k]) * source * 1.001 + 1e-12) << d << " bin " << k;
        EXPECT_GT(along.in_scattered[k], 0.0f);
      }
    }
  }
}

TEST(FogRender, ShadowsTakeTheBeamsAndTheFieldsSunSideLight) {
  // A ray that passes through the block's shadow gathers less light from the fog than
  // the same ray without the block: with multiple scattering, by exactly the sun's beams
  // (the closed form) and the field's light from the sun's side of the sky
  // (FogSkyLight::sun_side_in_scattered) over the part in shadow.
  Scene scene = street_scene();
  scene.fog = FogSettings{};
  scene.fog->density_at_ground = 0.3;
  scene.fog->multiple_scattering = true;
  const Atmosphere atmosphere(scene.atmosphere);
  const SkyModel sky(atmosphere, direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg), 1.6);
  const Vec3& to_sun = sky.to_sun();  // the sun as seen, where the fog's light comes from
  const std::vector<const TriangleMesh*> with_block{&scene.objects[0].mesh, &scene.objects[1].mesh};
  const std::vector<const TriangleMesh*> without{&scene.objects[0].mesh};
  const Vec3 origin{-80, 40, 2};  // in the block's shadow line: north-west of it, sun from the south-south-east
  const FogSkyLight field(FogLayer(*scene.fog), sky);
  ASSERT_TRUE(field.has_sun_side());
  const Ray ray{origin, normalize(Vec3{1, 0, 0})};  // eastward, behind the block
  const double length = 160;
  const SunShadowVolumes shadows(with_block, to_sun);
  const std::vector<Interval> lit = shadows.sunlit_intervals(ray, 0, length);
  double shadowed = length;
  for (const Interval& l : lit) shadowed -= l.end - l.begin;
  ASSERT_GT(shadowed, 5.0);  // the geometry does put part of the ray in shadow
  // The light lost over the shadowed parts, from the closed form and the field.
  Spectrum beams = fog_sun_inscatter(field.layer(), origin, ray.direction, to_sun, 0, length,
                                     sky.direct_sun(60.0).spectrum(), field.sun_depth_scale());
  for (const Interval& l : lit)
    beams -= fog_sun_inscatter(field.layer(), origin, ray.direction, to_sun, l.begin, l.end,
                               sky.direct_sun(60.0).spectrum(), field.sun_depth_scale());
  Spectrum sun_side(0.0f);
  double from = 0;
  for (const Interval& l : lit) {
    if (l.begin > from) sun_side += field.sun_side_in_scattered(origin, ray.direction, from, l.begin);
    from = l.end;
  }
  if (length > from) sun_side += field.sun_side_in_scattered(origin, ray.direction, from, length);
  EXPECT_GT(luminance(sun_side), 0.05 * luminance(beams));  // the field's part is not negligible
  const Spectrum expected = beams + sun_side;
  // Tabulated for another camera, FogMedium integrates along the ray as the field does:
  // the same to rounding. From its own camera it reads its table, which holds the
  // field's sun-side light by distance and interpolates it (within 2 %).
  for (const Vec3& camera : {Vec3{0, 0, 500}, origin}) {
    const std::unique_ptr<RayTracer> with_block_tracer = tracer_of(with_block), without_tracer = tracer_of(without);
    const FogMedium shaded(*scene.fog, with_block, *with_block_tracer, sky, camera),
        open(*scene.fog, without, *without_tracer, sky, camera);
    ASSERT_LT(open.sun_depth_scale(), 0.9);  // the beams carry the forward spike's light
    const Spectrum difference =
        (open.along(ray, length).near.in_scattered - shaded.along(ray, length).near.in_scattered).spectrum();
    const double tolerance = camera == origin ? 0.02 : 1e-4;
    for (int k = 0; k < kSpectralBins; k += 7)
      EXPECT_NEAR(difference[k], expected[k], tolerance * expected[k] + 1e-9) << "bin " << k;
  }
}

TEST(FogRender, CameraTableMatchesDirectIntegrationInDenseFog) {
  // The camera's table of sky light in fog (fog_medium.h) against Eq. 14's integration
  // along the same ray (a FogMedium tabulated for another camera integrates directly).
  // V = 100 m: the fog saturates within the table's first slices (22, 87, 195 m on a
  // level row), where interpolating in distance erred by up to 28 %; read by the fog's
  // transmittance it is within 1.5 %, the tolerance: the direct integration itself is
  // good to ~0.5 % in this fog (its trapezoids against 200 times finer ones), and the
  // table's rows are 1° apart at 45°.
  Scene scene = street_scene();
  scene.fog = FogSettings{};
  scene.fog->density_at_ground = 0;
  scene.fog->ground_visibility_m = 100;
  scene.fog->scale_height_m = 1e6;
  scene.fog->top_altitude_m = 400;
  const Atmosphere atmosphere(scene.atmosphere);
  const SkyModel sky(atmosphere, direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg), 1.6);
  const std::vector<const TriangleMesh*> no_meshes;
  const Vec3 camera = scene.camera.position;
  const std::unique_ptr<RayTracer> tracer = tracer_of(no_meshes);
  const FogMedium tabulated(*scene.fog, no_meshes, *tracer, sky, camera),
      direct(*scene.fog, no_meshes, *tracer, sky, camera + Vec3{0, 0, 50});
  double worst = 0;
  for (const double elevation_deg : {0.0, 0.03, -0.2, 2.0, 10.0, 45.0}) {
    const Ray ray{camera, direction_from_altitude_azimuth(elevation_deg, 20)};
    for (const double d : {3.0, 15.0, 40.0, 60.0, 100.0, 140.0, 250.0, 600.0}) {
      const double got = luminance(tabulated.along(ray, d).near.in_scattered.spectrum());
      const double want = luminance(direct.along(ray, d).near.in_scattered.spectrum());
      EXPECT_NEAR(got, want, 0.015 * want) << elevation_deg << "° at " << d << " m";
      worst = std::max(worst, std::abs(got / want - 1));
    }
  }
  std::printf("camera table vs direct integration, V = 100 m: worst %.2e\n", worst);
}

}  // namespace
}  // namespace skylit
