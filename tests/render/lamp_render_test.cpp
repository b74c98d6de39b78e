// Lamps in rendered scenes (render/scene_lamps.h): the illuminance they put on the
// ground (inverse square and cosine law, through the renderer's spectra and observer),
// their shadows, and their glow in homogeneous fog against the closed form of Sun et
// al. (2005); the lamp itself seen as a point in the image.
#include <gtest/gtest.h>

#include <cmath>

#include "../reference_quadrature.h"
#include "skylit/geometry/primitives.h"
#include "skylit/lights/lamp_spectrum.h"
#include "skylit/material/optical_constants.h"
#include "skylit/render/renderer.h"
#include "skylit/render/scene_lamps.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

constexpr double kReflectance = 0.5;

// A dark night (sun 40° below the horizon: no twilight; no night sky), a grey ground, one isotropic
// 1000 cd LED lamp 5 m up.
// A fog of one extinction coefficient everywhere the lamps' rays go (from 50 m below the
// ground to 1 km up), scattering isotropically: the closed forms' medium.
FogSettings homogeneous_isotropic_fog(double extinction_per_m) {
  FogSettings fog;
  fog.density_at_ground = 1.0;
  fog.unit_density_extinction_per_m = extinction_per_m;
  fog.scale_height_m = std::numeric_limits<double>::infinity();
  fog.bottom_altitude_m = -50;
  fog.top_altitude_m = 1000;
  fog.phase = FogPhase::henyey_greenstein;
  fog.asymmetry = 0;
  return fog;
}

Scene night_scene() {
  Scene scene;
  scene.camera = Camera{{0, -20, 1.6}, {0, 0, 0}, {0, 0, 1}, 50.0};
  scene.sun = Sun{-40, 180};
  scene.atmosphere.night_sky.natural = false;  // the lamps alone (docs/night-sky.md)
  scene.materials.push_back({"ground", DiffuseMaterial{Spectrum(static_cast<float>(kReflectance))}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 2000), 0});
  LampSpectrumSettings led;
  scene.lights.push_back(
      {"lamp", Luminaire({0, 0, 5}, IntensityDistribution::isotropic(1000.0)), lamp_spectrum_per_candela(led)});
  scene.render = RenderSettings{16, 16, std::nullopt, 1};
  return scene;
}

double ground_luminance(const Renderer& renderer, double x) {
  return luminance(renderer.radiance(Ray{{x, 0, 1}, {0, 0, -1}}));
}

TEST(LampRender, GroundLuminanceFollowsInverseSquareAndCosineLaw) {
  // E = I cos θ / d²; a Lambertian ground of reflectance ρ shows L = ρE/π. Below the
  // lamp 40 lx. Tolerance 0.5 % plus the night sky's own light (bounded below).
  const Scene scene = night_scene();
  const Renderer renderer(scene);
  Scene dark = scene;
  dark.lights.clear();
  const Renderer sky_only(dark);
  for (double x : {0.0, 2.0, 5.0, 12.0}) {
    const double d2 = x * x + 25.0, cos_theta = 5.0 / std::sqrt(d2);
    const double expected = kReflectance * 1000.0 * cos_theta / d2 / kPi;
    const double sky = ground_luminance(sky_only, x);
    EXPECT_LT(sky, 1e-3 * expected) << "the night sky at x = " << x;
    EXPECT_NEAR(ground_luminance(renderer, x), expected, 0.005 * expected + sky) << "x = " << x;
  }
}

TEST(LampRender, AnObjectBetweenLampAndGroundCastsAShadow) {
  Scene scene = night_scene();
  scene.materials.push_back({"board", DiffuseMaterial{Spectrum(0.3f)}});
  scene.objects.push_back({"board", make_box({3, -1, 2}, {5, 1, 2.2}), 1});  // over x ≈ 4–8 m on the ground
  const Renderer renderer(scene);
  const Scene open_scene = night_scene();
  const Renderer open(open_scene);
  EXPECT_LT(ground_luminance(renderer, 6.0), 1e-3 * ground_luminance(open, 6.0));     // in the shadow
  EXPECT_NEAR(ground_luminance(renderer, 12.0), ground_luminance(open, 12.0), 1e-6);  // beyond it
  EXPECT_NEAR(ground_luminance(renderer, 1.0), ground_luminance(open, 1.0), 1e-6);    // before it
}

// Sun et al. 2005 for an isotropic lamp (intensity I) in a homogeneous isotropic
// medium of extinction σ, a ray passing at h from the lamp with its foot s0 ahead:
// L = σ I e^{−σ s0}/(2π h) ∫_{θ0/2}^{π/2} e^{−σ h tan ξ} dξ, θ0 = atan2(h, s0).
double glow_closed_form(double sigma, double intensity, double h, double s0) {
  const double theta0 = std::atan2(h, s0);
  return sigma * intensity * std::exp(-sigma * s0) / (2 * kPi * h) *
         testing::integrate([&](double xi) { return std::exp(-sigma * h * std::tan(xi)); }, theta0 / 2, kPi / 2 - 1e-12,
                            1e-12);
}

TEST(LampRender, GlowInHomogeneousFogFallsOffAsTheClosedForm) {
  // Horizontal view rays passing the lamp at growing distances, in a homogeneous fog
  // (σ = 0.01 m⁻¹, isotropic phase) with nothing in the way: the rendered luminance
  // is the closed form's (the LED spectrum is one candela per candela), less at most
  // kDroppedGlowShare for the ray's part beyond the lamp's reach, within 1e-3 (the
  // quadrature on a ray split at the reach, measured 7e-4; on whole rays it is within
  // 1e-4, tests/media/lamp_in_scatter_test.cpp) plus 1e-6 cd/m² of sky.
  Scene scene = night_scene();
  scene.objects.clear();
  scene.materials.resize(1);
  scene.objects.push_back({"ground", make_ground_plane({0, 0, -100}, 2000), 0});
  scene.lights[0] = {"lamp", Luminaire({0, 30, 10}, IntensityDistribution::isotropic(1000.0)),
                     scene.lights[0].spectrum_per_candela};
  scene.fog = homogeneous_isotropic_fog(0.01);
  const Renderer renderer(scene);
  double previous = std::numeric_limits<double>::infinity();
  for (double offset : {0.5, 2.0, 8.0, 30.0}) {
    const double got = luminance(renderer.radiance(Ray{{offset, 0, 10}, {0, 1, 0}}));
    const double expected = glow_closed_form(0.01, 1000.0, offset, 30.0);
    EXPECT_LE(got, expected * (1 + 1e-3) + 1e-6) << "offset " << offset;
    EXPECT_GE(got, expected * (1 - kDroppedGlowShare - 1e-3) - 1e-6) << "offset " << offset;
    EXPECT_LT(got, previous);
    previous = got;
  }
}

TEST(LampRender, UntestedFaintLampsAddAtMostTheirShare) {
  // One bright lamp over the point and eight faint ones far off behind a wall, which
  // together would give 2 % of the bright one's light: more than kUntestedShare, so
  // occlusion rays must go to them until what is left untested is under that share.
  // The result may exceed the exact one (the bright lamp only) by at most
  // kUntestedShare; counting all the faint ones unshadowed would be 2 % too bright.
  // With the bright lamp shadowed as well, every lamp is tested and the point is dark.
  Scene scene = night_scene();  // the bright lamp: 1000 cd at (0, 0, 5)
  double faint_lux = 0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 p{40.0 + i, 0, 5};
    scene.lights.push_back(
        {"faint", Luminaire(p, IntensityDistribution::isotropic(1300.0)), scene.lights[0].spectrum_per_candela});
    faint_lux += 1300.0 * 5 / std::pow(length(p), 3);
  }
  ASSERT_GT(faint_lux, 0.015 * 40.0);  // the faint lamps matter beyond the share
  scene.materials.push_back({"wall", DiffuseMaterial{Spectrum(0.3f)}});
  scene.objects.push_back({"wall", make_box({30, -50, 0}, {31, 50, 20}), 1});
  const double exact = kReflectance * 1000.0 / 25.0 / kPi;
  const double got = ground_luminance(Renderer(scene), 0.0);
  EXPECT_GE(got, exact * (1 - 1e-6));
  EXPECT_LE(got, exact * (1 + kUntestedShare));
  scene.objects.push_back({"roof", make_box({-3, -3, 3}, {3, 3, 3.2}), 1});  // over the point
  EXPECT_LT(ground_luminance(Renderer(scene), 0.0), 1e-6 * exact);
}

TEST(LampRender, HiddenLampMakesNoHighlightOnGlossyGround) {
  // A glossy ground (a coated dark body, rms slope 0.05) lit by one lamp overhead; a
  // second lamp where its highlight would be seen, but behind a wall. Its illuminance at
  // the point is a small share of the first's, yet its highlight would outshine it:
  // the wall must hide it (the lamps are ranked by the light they reflect toward the
  // viewer, highlight included).
  Scene scene = night_scene();
  scene.materials[0] = {"ground", CookTorranceMaterial(constant_ior(1.5), 0.05, Spectrum(0.1f))};
  const Vec3 eye{-20, 0, 2};         // looking at the ground point (0, 0, 0)
  const Vec3 mirror_lamp{60, 0, 6};  // where the view's mirror direction points
  const double without = [&] { return luminance(Renderer(scene).radiance(Ray{eye, normalize(-eye)})); }();
  scene.lights.push_back({"hidden", Luminaire(mirror_lamp, IntensityDistribution::isotropic(1000.0)),
                          scene.lights[0].spectrum_per_candela});
  scene.materials.push_back({"wall", DiffuseMaterial{Spectrum(0.3f)}});
  scene.objects.push_back({"wall", make_box({30, -50, 0}, {31, 50, 20}), 1});
  const double with_hidden = luminance(Renderer(scene).radiance(Ray{eye, normalize(-eye)}));
  EXPECT_NEAR(with_hidden, without, 1e-6 * without);
}

TEST(LampRender, LampSeenDirectlyLightsItsPixel) {
  // The camera looks at the lamp: its pixel holds the lamp's illuminance at the camera
  // spread over the pixel's solid angle, so pixel luminance × solid angle = I/d² (lx),
  // to the air's transmittance over 20 m (> 0.99).
  Scene scene = night_scene();
  scene.camera = Camera{{0, -20, 5}, {0, 0, 5}, {0, 0, 1}, 20.0};
  scene.render = RenderSettings{33, 33, std::nullopt, 1};
  const XyzImage image = Renderer(scene).render({1, {}});
  const ImageCamera camera(scene.camera, 33, 33);
  const double solid_angle = camera.pixel_solid_angle(16.5, 16.5);
  const double expected = 1000.0 / (20.0 * 20.0);
  EXPECT_NEAR(image.at(16, 16).y * solid_angle, expected, 0.01 * expected);
  EXPECT_LT(image.at(15, 16).y * solid_angle, 1e-3 * expected);  // only that pixel
}

namespace reach {

// Homogeneous fog (σ = 0.01 m⁻¹, isotropic phase) around an isotropic 1000 cd lamp at
// (0, 0, 10), with a board x ∈ [−3, 3] whose near face is at y = y_board; the board's
// shadow on a horizontal view ray from (30, y_ray, 10) toward −x is |x| < 3 y_ray/y_board.
constexpr double kSigma = 0.01, kCandela = 1000.0, kPhase = 1 / (4 * kPi);

Scene fog_scene(double y_board) {
  Scene scene = night_scene();
  scene.objects.clear();
  scene.objects.push_back({"ground", make_ground_plane({0, 0, -100}, 4000), 0});
  if (y_board > 0) scene.objects.push_back({"board", make_box({-3, y_board, -50}, {3, y_board + 1, 60}), 0});
  scene.lights[0] = {"lamp", Luminaire({0, 0, 10}, IntensityDistribution::isotropic(kCandela)),
                     scene.lights[0].spectrum_per_candela};
  scene.fog = homogeneous_isotropic_fog(kSigma);
  return scene;
}

// The glow the board's shadow takes from the ray (single scattering, by quadrature).
double shadow_loss(double y_ray, double y_board) {
  const double half = 3 * y_ray / y_board;
  return testing::integrate(
      [&](double x) {
        const double r2 = x * x + y_ray * y_ray;
        return kSigma * kCandela * kPhase * std::exp(-kSigma * (std::sqrt(r2) + 30 - x)) / r2;
      },
      -half, half, 1e-12);
}

double glow(double y_ray, double y_board) {
  const Scene scene = fog_scene(y_board);
  return luminance(Renderer(scene).radiance(Ray{{30, y_ray, 10}, {-1, 0, 0}}));
}

}  // namespace reach

TEST(LampRender, GlowShadowsAreExactWithinTheReachAndBeyondItWhenTheyMatter) {
  // Within kLampReachM (100 m) the board's shadow takes from the glow what the
  // quadrature says (tolerance 1e-3 of the glow: the glow's own quadrature, 3e-4).
  ASSERT_NEAR(kLampReachM, 100.0, 1e-9);
  const double open_near = reach::glow(40, 0), shadowed_near = reach::glow(40, 20);
  EXPECT_NEAR(open_near - shadowed_near, reach::shadow_loss(40, 20), 1e-3 * open_near);
  // Beyond it (the ray 105 m off) the ray meets no lamp's glow within a reach, so what
  // lies beyond is no small share of anything found: the shadow is looked for there
  // too, with the same tolerance (it takes over 1 % of the glow: it does matter).
  const double open_far = reach::glow(105, 0), shadowed_far = reach::glow(105, 60);
  const double loss = reach::shadow_loss(105, 60);
  EXPECT_GT(loss, 0.01 * open_far);
  EXPECT_NEAR(open_far - shadowed_far, loss, 1e-3 * open_far);
}

}  // namespace
}  // namespace skylit
