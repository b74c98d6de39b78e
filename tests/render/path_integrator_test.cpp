// The path-traced reference (render/path_integrator.h) against closed forms and
// independent quadratures, and against the fast method where that one is exact.
// Tolerances are three standard errors of the estimate (the chance that a correct
// integrator fails one comparison is 0.3 %; the seeds are fixed, so each test's result
// does not change from run to run) plus the stated error of the independent value.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skylit/geometry/primitives.h"
#include "skylit/lights/lamp_spectrum.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// The mean and standard error of n path samples of one bin (or of luminance) along a ray.
struct Estimate {
  double mean = 0, standard_error = 0;
};

template <typename Value>
Estimate estimate(const PathIntegrator& integrator, const Ray& ray, int n, Value&& value) {
  double sum = 0, squares = 0;
  for (int i = 0; i < n; ++i) {
    CounterRandom random(3, 0, static_cast<uint64_t>(i));
    const double v = value(integrator.sample(ray, random));
    sum += v;
    squares += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1))};
}

Scene open_ground(double reflectance) {
  Scene scene;
  scene.camera = Camera{{0, -20, 20}, {0, 0, 0}, {0, 0, 1}, 50.0};
  scene.sun = Sun{40, 160};
  scene.materials.push_back({"ground", DiffuseMaterial{Spectrum(static_cast<float>(reflectance))}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 4000), 0});
  scene.render = RenderSettings{24, 16, std::nullopt, 1};
  scene.render.integrator = Integrator::path;
  scene.render.samples_per_pixel = 8;
  return scene;
}

TEST(PathIntegrator, NonAbsorbingSceneInAWhiteFurnaceIsAsBrightAsItsSurroundings) {
  // White (ρ = 1) ground and tower under radiance 1 from everywhere: every surface
  // sends back exactly 1, whatever the bounces between tower and ground (energy
  // conservation), so the estimate of any ray is 1 within its standard error.
  Scene scene = open_ground(1.0);
  scene.objects.push_back({"tower", make_box({-5, -5, 0}, {5, 5, 30}), 0});
  const PreparedScene prepared(scene);
  const PathIntegrator furnace(prepared, TestEnvironment{Spectrum(1.0f), Spectrum(1.0f)});
  for (const Vec3& target : {Vec3{0, -5, 10}, Vec3{0, -6, 0.01}, Vec3{-3, -5.5, 0.2}, Vec3{20, 20, 0}}) {
    const Vec3 eye{3, -40, 8};
    const Estimate e = estimate(furnace, Ray{eye, normalize(target - eye)}, 20000,
                                [](const Radiance& r) { return static_cast<double>(r[20]); });
    EXPECT_NEAR(e.mean, 1.0, 3 * e.standard_error + 1e-6) << target.x << " " << target.y << " " << target.z;
    EXPECT_LT(e.standard_error, 0.01);  // the comparison is a real one
  }
}

TEST(PathIntegrator, OpenLambertianGroundReflectsRhoEOverPi) {
  // An unoccluded Lambertian ground under the sun and the sky: ρ (E_sun sin h + E_sky)/π,
  // seen through the camera's air, with E_sky from a 256 × 512 midpoint quadrature of
  // the sky model's radiance over the upper hemisphere (0.1 % from the converged
  // integral at this resolution, checked by halving it).
  const double rho = 0.4;
  const Scene scene = open_ground(rho);
  const PreparedScene prepared(scene);
  const PathIntegrator path(prepared);
  const SkyModel& sky = prepared.sky();
  Spectrum e_sky(0.0f);
  constexpr int kTheta = 256, kPhi = 512;
  for (int i = 0; i < kTheta; ++i)
    for (int j = 0; j < kPhi; ++j) {
      const double theta = (i + 0.5) * (kPi / 2) / kTheta, phi = (j + 0.5) * 2 * kPi / kPhi;
      const Vec3 l{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      e_sky += sky.sky_radiance_near_ground(l).spectrum() *
               static_cast<float>(std::cos(theta) * std::sin(theta) * (kPi / 2 / kTheta) * (2 * kPi / kPhi));
    }
  const Spectrum e_sun = sky.direct_sun(0.0).spectrum() * static_cast<float>(std::sin(radians(scene.sun.altitude_deg)));
  const Vec3 eye = scene.camera.position, target{2, 3, 0};
  const Ray ray{eye, normalize(target - eye)};
  const MediumStretch air = sky.aerial_perspective(ray.direction, length(target - eye));
  const double expected = luminance(air.seen_through(Radiance((e_sky + e_sun) * static_cast<float>(rho / kPi))));
  const Estimate e = estimate(path, ray, 4000, [](const Radiance& r) { return luminance(r); });
  EXPECT_NEAR(e.mean, expected, 3 * e.standard_error + 1e-3 * expected);
  EXPECT_LT(e.standard_error, 0.01 * expected);
  // The fast method, exact here but for its table of sky irradiance over orientations
  // (within 0.9 % of a dense quadrature, docs/sky-light.md): within that of the sky's
  // share plus three standard errors.
  const Renderer fast(scene);
  const double sky_share = luminance(Radiance(e_sky * static_cast<float>(rho / kPi))) / expected;
  EXPECT_NEAR(luminance(fast.radiance(ray)), e.mean, 3 * e.standard_error + 0.009 * sky_share * expected);
}

TEST(PathIntegrator, LampOnGroundAgreesWithClosedFormAndFastMethod) {
  // Night (sun 40° down), one isotropic 1000 cd lamp 5 m above a grey ground: the ground
  // 3 m from the lamp's foot reflects ρ/π · I cos θ / d² (lamp spectrum per candela),
  // exactly in both integrators (the fast one through its intensity map, within 0.3 %).
  Scene scene = open_ground(0.5);
  scene.sun = Sun{-40, 180};
  LampSpectrumSettings led;
  scene.lights.push_back(
      {"lamp", Luminaire({0, 0, 5}, IntensityDistribution::isotropic(1000.0)), lamp_spectrum_per_candela(led)});
  const Renderer fast(scene);
  const PathIntegrator path(fast.prepared());
  const Vec3 eye{3, -1, 1.5}, target{3, 0, 0};
  const Ray ray{eye, normalize(target - eye)};
  const double d2 = 9 + 25, cos_theta = 5 / std::sqrt(d2);
  const double transmittance =
      luminance(fast.sky().aerial_perspective(ray.direction, length(target - eye)).transmittance.spectrum()) /
      luminance(Spectrum(1.0f));
  const double closed =
      0.5 / kPi * 1000 * cos_theta / d2 * luminance(scene.lights[0].spectrum_per_candela) * transmittance;
  const Estimate e = estimate(path, ray, 2000, [](const Radiance& r) { return luminance(r); });
  EXPECT_NEAR(e.mean, closed, 3 * e.standard_error + 2e-3 * closed);
  EXPECT_NEAR(luminance(fast.radiance(ray)), e.mean, 3 * e.standard_error + 3e-3 * closed);
}

TEST(PathIntegrator, BytesDoNotDependOnThreads) {
  Scene scene = open_ground(0.3);
  scene.objects.push_back({"tower", make_box({-5, -5, 0}, {5, 5, 30}), 0});
  scene.camera = Camera{{3, -40, 8}, {0, 0, 10}, {0, 0, 1}, 60.0};
  const Renderer renderer(scene);
  std::vector<HugePageVector<float>> images;
  for (int threads : {1, 2, 7}) {
    const Renderer::Result result = renderer.render_with_error({threads, {}});
    ASSERT_TRUE(result.standard_error.has_value());
    images.push_back(result.image.xyz);
    images.back().insert(images.back().end(), result.standard_error->xyz.begin(), result.standard_error->xyz.end());
  }
  EXPECT_EQ(images[0], images[1]);
  EXPECT_EQ(images[0], images[2]);
}

TEST(PathIntegrator, CloudInAWhiteFurnaceIsAsBrightAsItsSurroundings) {
  // A non-absorbing cloud (optical depth ~20 at its centre) under radiance 1 from
  // everywhere: seen from below, from the side and through its edge it reads 1, whatever
  // the number of scattering events inside (delta tracking, the droplet phase function's
  // sampling and the ratio-tracked shadow rays all keep the energy).
  Scene scene;
  scene.camera = Camera{{0, 0, 2}, {0, 0, 1000}, {0, 1, 0}, 50.0};
  CloudShape cloud;
  cloud.altitude = 1200;
  cloud.semi_axis_a = cloud.semi_axis_b = 800;
  cloud.max_thickness = 400;
  scene.clouds.push_back(cloud);
  const PreparedScene prepared(scene);
  const PathIntegrator furnace(prepared, TestEnvironment{Spectrum(1.0f), Spectrum(1.0f)});
  for (const Vec3& target : {Vec3{0, 0, 1200}, Vec3{700, 0, 1200}, Vec3{0, 0, 1300}}) {
    const Vec3 eye = target.z > 1250 ? Vec3{-3000, 0, 1300} : Vec3{0, -100, 2};
    const Estimate e = estimate(furnace, Ray{eye, normalize(target - eye)}, 16000,
                                [](const Radiance& r) { return static_cast<double>(r[20]); });
    EXPECT_NEAR(e.mean, 1.0, 3 * e.standard_error + 1e-6) << target.x << " " << target.z;
    EXPECT_LT(e.standard_error, 0.03);
  }
}

}  // namespace
}  // namespace skylit
