// The fast method's fog with multiple scattering (media/fog_diffuse_field.h) against the
// path-traced reference (render.integrator = "path"): a homogeneous fog layer 100 m
// deep, the camera in it at 1.6 m, the real sky above, over a black ground (the
// atmosphere's ground albedo 0, so that the path tracer's far ground below the fog and
// the fast method's bottom boundary are the same). The fog's luminance at several view
// elevations, for optical depths and sun altitudes. CI runs a subset; the full grid of
// issue 13 (optical depths 0.1, 1, 3, 10, 30; sun 10°, 30°, 60°; five elevations; toward
// and away from the sun) runs with SKYLIT_FOG_MS_FULL=1 and prints every ratio.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "../media/fog_slab.h"
#include "path_luminance.h"
#include "skylit/geometry/primitives.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/path_integrator.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

constexpr double kTop = 100;

// `asymmetry` < 1: a Henyey–Greenstein fog of that g; otherwise the droplet fit.
Scene fog_scene(double optical_depth, double sun_altitude_deg, double asymmetry) {
  Scene scene;
  scene.camera = Camera{{0, 0, 1.6}, {0, 100, 1.6}, {0, 0, 1}, 50.0};
  scene.sun = Sun{sun_altitude_deg, 180};
  scene.atmosphere.ground_albedo = 0.0;
  FogSettings fog = testing::uniform_fog_slab(optical_depth, kTop);
  if (asymmetry < 1) {
    fog.phase = FogPhase::henyey_greenstein;
    fog.asymmetry = asymmetry;
  }
  fog.multiple_scattering = !std::getenv("SKYLIT_FOG_MS_PAPER");  // the grid in the paper's mode
  scene.fog = fog;
  return scene;
}

using testing::Estimate;
using testing::path_luminance;

// The fog's luminance from both methods at the given elevations and view azimuths;
// the fast one within 10 % plus three standard errors of the reference. Returns the
// worst |ratio − 1|.
double compare(double optical_depth, double sun_altitude_deg, double asymmetry, const std::vector<double>& elevations,
               const std::vector<double>& azimuths, int paths) {
  const Scene scene = fog_scene(optical_depth, sun_altitude_deg, asymmetry);
  const Renderer fast(scene);
  const PathIntegrator path(fast.prepared());
  double worst = 0;
  for (double azimuth : azimuths)
    for (double elevation : elevations) {
      const Ray ray{scene.camera.position, direction_from_altitude_azimuth(elevation, azimuth)};
      const double expected = luminance(fast.radiance(ray));
      const Estimate reference = path_luminance(path, ray, paths, 17);
      const double ratio = expected / reference.mean;
      worst = std::max(worst, std::abs(ratio - 1));
      std::printf(
          "[FogMS] g %.2f tau %5.1f sun %4.0f view az %4.0f el %4.0f: fast %10.1f path %10.1f ± %7.1f cd/m2, ratio "
          "%.3f\n",
          asymmetry, optical_depth, sun_altitude_deg, azimuth, elevation, expected, reference.mean,
          reference.standard_error, ratio);
      EXPECT_NEAR(expected, reference.mean, 0.1 * reference.mean + 3 * reference.standard_error)
          << "τ " << optical_depth << ", sun " << sun_altitude_deg << "°, view " << azimuth << "°/" << elevation << "°";
    }
  return worst;
}

TEST(FogMultipleScattering, MatchesThePathTracedReferenceWhereTheFieldIsAzimuthallySymmetric) {
  // CI: the sun at 30°, three elevations, looking across the sun's plane (azimuth 90°
  // from it), 4000 paths (standard errors 2–8 %). An isotropic fog (its scattered light
  // has no azimuthal structure, so the m = 0 solution is the whole answer) at optical
  // depths 1 and 10, and a Henyey–Greenstein fog of g = 0.85 at 10, where the light is
  // diffuse enough: measured within 2 % and 6 %. In the paper's single scattering the
  // same views read 0.1–44 % of the reference (docs/fog.md).
  for (double tau : {1.0, 10.0}) compare(tau, 30, 0.0, {2, 30, 85}, {90}, 4000);
  compare(10.0, 30, 0.85, {2, 30, 85}, {90}, 4000);
}

TEST(FogMultipleScattering, FollowsTheSunInAzimuthWithTheDropletPhaseFunction) {
  // The droplet fit (15 µm) at optical depth 1 with a low sun (10°), 30° up, looking away
  // from the sun and 30° from it: the light scattered more than once still travels near
  // the sun there, and the azimuthal mean alone read 1.84 and 0.71 of the reference;
  // with the field's Fourier terms, 1.05 and 1.15 (standard errors 4 % and 10 % with
  // 2000 paths). Within 10 % plus three standard errors.
  compare(1.0, 10, 1.0, {30}, {0, 150}, 2000);
}

TEST(FogMultipleScattering, CountsTheSunsSingleScatteringOnceWithASharpPeak) {
  // Henyey–Greenstein g = 0.99 at optical depth 1, sun 60°, looking 30° up and 30° in
  // azimuth from it (36° from the sun): δ-M's truncated phase function puts 58 % too much
  // light 30–60° from the sun, and while the view's diffuse radiance held the sun's first
  // scattering by it the fast method read 1.23 of the reference; with the sun's single
  // scattering in the beams alone, 1.08 (standard error 0.5 % with 4000 paths).
  compare(1.0, 60, 0.99, {30}, {150}, 4000);
}

// A street in the fog: a wall 20 m high facing the sun (at azimuth 180°) across a block
// 6 m high, a 15 m building on the sun's side, all grey 0.3 like the ground and the
// field's ground below the layer.
Scene fog_street(double optical_depth, double sun_altitude_deg, double asymmetry) {
  Scene scene = fog_scene(optical_depth, sun_altitude_deg, asymmetry);
  scene.atmosphere.ground_albedo = 0.3;
  scene.materials.push_back({"grey", DiffuseMaterial{Spectrum(0.3f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 20000), 0});
  scene.objects.push_back({"wall", make_box({-30, 40, 0}, {30, 60, 20}), 0});
  scene.objects.push_back({"block", make_box({-30, 25, 0}, {30, 32, 6}), 0});
  scene.objects.push_back({"south", make_box({-30, -40, 0}, {30, -20, 15}), 0});
  return scene;
}

// A surface seen from 0.3 m in front of it, so that its own light is what is measured.
struct SurfaceView {
  const char* surface;
  Vec3 from, toward;
};

// The luminance along `ray` from both methods, printed with their ratio; with a
// `relative_tolerance`, the fast one within it plus three standard errors of the reference.
void compare_along(const Scene& scene, const Ray& ray, const std::string& label, int paths, uint64_t seed,
                   std::optional<double> relative_tolerance) {
  const Renderer fast(scene);
  const PathIntegrator path(fast.prepared());
  const double expected = luminance(fast.radiance(ray));
  const Estimate reference = path_luminance(path, ray, paths, seed);
  std::printf("[FogMS] %s: fast %.2f path %.2f ± %.2f cd/m2, ratio %.3f ± %.3f\n", label.c_str(), expected,
              reference.mean, reference.standard_error, expected / reference.mean,
              expected * reference.standard_error / (reference.mean * reference.mean));
  if (relative_tolerance) {
    EXPECT_NEAR(expected, reference.mean, *relative_tolerance * reference.mean + 3 * reference.standard_error) << label;
  }
}

// The surfaces seen from their views; those of the first `asserted` views within 10 %
// plus three standard errors of the reference.
void compare_surfaces(const Scene& street, const std::vector<SurfaceView>& views, size_t asserted, int paths) {
  for (size_t i = 0; i < views.size(); ++i) {
    const SurfaceView& view = views[i];
    Scene scene = street;
    scene.camera = Camera{view.from, view.from + view.toward, {0, 0, 1}, 50.0};
    compare_along(scene, Ray{view.from, normalize(view.toward)}, view.surface, paths, 23,
                  i < asserted ? std::optional<double>(0.1) : std::nullopt);
  }
}

const std::vector<SurfaceView> kStreetViews{
    {"open ground, 300 m from the buildings", {300, 0, 0.3}, {0, 0.5, -1}},
    {"sunlit wall at 15 m", {0, 39.7, 15}, {0, 1, 0}},
    {"sunlit wall at 8 m, facing the block", {0, 39.7, 8}, {0, 1, 0}},
    {"the block's top", {0, 28, 6.3}, {0, 0.2, -1}},
    {"the block's sunlit face", {0, 24.7, 3}, {0, 1, 0}},
    {"ground in a building's shadow", {0, 0, 0.3}, {0, 0.5, -1}},
    {"ground in the 8 m gap", {0, 36, 0.3}, {0, 0.3, -1}},
    {"shaded wall at 5 m, toward the sun", {0, -19.7, 5}, {0, -1, 0}},
    {"shaded wall at 12 m, toward the sun", {0, -19.7, 12}, {0, -1, 0}},
    {"the wall's shaded back at 10 m", {0, 60.3, 10}, {0, -1, 0}},
};

TEST(FogMultipleScattering, LightsSurfacesInTheFogWithTheFogsOwnLight) {
  // Surfaces in fog_street inside a Henyey–Greenstein fog (g = 0.85) of optical depth 3
  // (100 m deep), sun 30°: the direct sun is down to e^−5 in the layer, so what lights
  // them is the fog's own light (media/fog_surface_light.h). The paper's sky light
  // scaled by J(z)/J read 0.17–0.26 of the reference here. Measured with 8000 paths
  // (standard errors 6–7 %): open ground 300 m from the buildings 0.98, the sunlit wall
  // at 15 m 1.07 and at 8 m (facing the block) 1.20, the block's top 1.05. Within 10 %
  // plus three standard errors. The other views of kStreetViews are not checked here
  // (docs/fog.md): near the buildings in the shade the fast method reads 1.1–1.3 in this
  // fog and up to 2 in thicker ones, since the buildings darken the fog around them,
  // which the horizontally uniform field cannot know. SKYLIT_FOG_MS_FULL=1 prints them
  // all for several fogs.
  const std::vector<SurfaceView> open_and_sunlit(kStreetViews.begin(), kStreetViews.begin() + 4);
  compare_surfaces(fog_street(3, 30, 0.85), open_and_sunlit, open_and_sunlit.size(), 8000);
}

TEST(FogMultipleScattering, SurfacesSeenThroughTheFogKeepTheLightScatteredStraightOn) {
  // A white wall (0.8) 40, 80 and 160 m away, 400 m wide and 60 m high, seen through a
  // Henyey–Greenstein fog of g = 0.99 (δ-M puts f = 0.85 of its scattering in the forward
  // spike) of optical depth 3 over its 100 m: 1.2, 2.4 and 4.8 along the view. The sun 3°
  // below the horizon, so that the reference converges (a sunlit fog this sharp needs
  // far more paths). Light scattered straight on still comes from the wall: seen through
  // the fog's full depth it read 0.89 and 0.90 of the reference at 40 and 80 m; with the
  // spike's gain (FogMedium::Along::forward_gain) 0.97, 0.99 and 0.97 (8000 paths,
  // standard errors 1.6 %). Within 5 % plus three standard errors.
  // Not asserted, and why (docs/fog.md, "Surfaces seen through the fog"): the fog in
  // front of the wall glows as the open layer does, which is right only where the wall
  // is about as bright as the layer's light from its side; a grey (0.3) wall here reads
  // 1.25–1.62, a black one 10–13 times the reference.
  Scene scene = fog_scene(3, -3, 0.99);
  scene.atmosphere.ground_albedo = 0.3;
  scene.materials.push_back({"grey", DiffuseMaterial{Spectrum(0.3f)}});
  scene.materials.push_back({"white", DiffuseMaterial{Spectrum(0.8f)}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 20000), 0});
  for (double distance : {40.0, 80.0, 160.0}) {
    Scene view = scene;
    view.objects.push_back({"wall", make_box({-200, distance, 0}, {200, distance + 10, 60}), 1});
    compare_along(view, Ray{view.camera.position, normalize(Vec3{0, 1, 0.05})},
                  "white wall " + std::to_string(static_cast<int>(distance)) + " m away", 8000, 29, 0.05);
  }
}

TEST(FogMultipleScattering, TheFogInFrontOfADarkWallLosesTheLightTheWallHides) {
  // A wall 400 m wide and 60 m high 80 m away, sunlit (the sun 20° up behind the camera),
  // seen through the droplets' fog of optical depth 3 over its 100 m; 4000 paths
  // (standard errors 6–9 %). The open layer's field sends the fog in front of the wall
  // the light travelling toward the camera from behind it, which the wall hides
  // (media/fog_behind_surface.h): a black wall read 2.36 and a grey one (0.3) 1.08 of the
  // reference; with the hidden light taken out, 1.33 and 0.96. The grey within 10 % plus
  // three standard errors, the black within 40 % (what is left: docs/fog.md).
  for (const auto& [albedo, tolerance] : {std::pair{0.3f, 0.1}, {0.0f, 0.4}}) {
    Scene scene = fog_scene(3, 20, 1.0);
    scene.atmosphere.ground_albedo = 0.3;
    scene.materials.push_back({"grey", DiffuseMaterial{Spectrum(0.3f)}});
    scene.materials.push_back({"wall", DiffuseMaterial{Spectrum(albedo)}});
    scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 20000), 0});
    scene.objects.push_back({"wall", make_box({-200, 80, 0}, {200, 90, 60}), 1});
    compare_along(scene, Ray{scene.camera.position, normalize(Vec3{0, 1, 0.05})},
                  "wall of albedo " + std::to_string(albedo).substr(0, 3) + " 80 m away in sunlit fog", 4000, 29,
                  tolerance);
  }
}

TEST(FogMultipleScattering, TheBlocksOfFig8cInTheirOwnShadowAgainstThePathTracer) {
  // examples/fig8c.json: a row of blocks between the camera and a low sun (14°); the
  // camera and the fog in front of the blocks' shaded faces lie in their shadow. Rays
  // from the camera to the middle block (concrete) and to the dark one (0.15) left of it,
  // 4000 paths each (standard errors 3–4 %). Without the field's sun-side light taken out
  // in the shadows the fast method read 3.06–4.40 (concrete) and 2.23–3.11 (dark) of the
  // reference; with it 0.96–1.18 and 1.17–1.56 (docs/fog.md). The concrete block within
  // 25 % plus three standard errors; the dark one within 70 %: in front of a dark face the
  // fog still glows with the open field's light from the face's direction, which the face
  // hides (the limit docs/fog.md describes for surfaces seen through the fog).
  const Scene scene =
      load_scene(std::string(SKYLIT_SOURCE_DIR) + "/examples/fig8c.json", {"fog.multiple_scattering=true"});
  const std::vector<std::pair<Vec3, double>> targets{
      {{4, 0, 12}, 0.25}, {{4, 0, 36}, 0.25}, {{-37, 4, 20}, 0.7}, {{-37, 4, 50}, 0.7}};
  for (const auto& [target, tolerance] : targets) {
    const Ray ray{scene.camera.position, normalize(target - scene.camera.position)};
    compare_along(scene, ray,
                  "Fig. 8c, toward (" + std::to_string(static_cast<int>(target.x)) + ", " +
                      std::to_string(static_cast<int>(target.y)) + ", " + std::to_string(static_cast<int>(target.z)) +
                      ")",
                  4000, 37, tolerance);
  }
}

TEST(FogMultipleScattering, TheGroundInFig8csShadowsAgainstThePathTracer) {
  // The grass in the blocks' long shadows before Fig. 8c's camera: lit by the fog around
  // it, much of which lies in the same shadows and scatters no sunlight toward it
  // (media/fog_shadowed_sunlight.h). Behind block 2, 64,000 paths (standard error 1 %):
  // with the open field's light from every direction the fast method read 1.09 of the
  // reference, now 0.99, asserted within 5 % plus three standard errors. Behind blocks 3
  // and 4, 16,000 paths (3–4 %): 1.04 and 1.20 before, 0.94 and 1.13 now (beside the
  // dark block 4: docs/fog.md), within 15 % plus three standard errors.
  const Scene scene =
      load_scene(std::string(SKYLIT_SOURCE_DIR) + "/examples/fig8c.json", {"fog.multiple_scattering=true"});
  struct Target {
    Vec3 point;
    int paths;
    double tolerance;
  };
  for (const Target& target :
       {Target{{-30, -70, 0}, 64000, 0.05}, Target{{4, -60, 0}, 16000, 0.15}, Target{{40, -50, 0}, 16000, 0.15}}) {
    const Ray ray{scene.camera.position, normalize(target.point - scene.camera.position)};
    compare_along(scene, ray,
                  "Fig. 8c's ground at (" + std::to_string(static_cast<int>(target.point.x)) + ", " +
                      std::to_string(static_cast<int>(target.point.y)) + ")",
                  target.paths, 41, target.tolerance);
  }
}

// A black wall 300 m wide and 45 m high, 50 m north of the camera, between it and a low
// sun in the north: the camera and the fog in front of the wall lie in its shadow.
Scene fog_in_a_walls_shadow(double optical_depth, double sun_altitude_deg) {
  Scene scene = fog_scene(optical_depth, sun_altitude_deg, 1.0);
  scene.sun = Sun{sun_altitude_deg, 0};
  scene.materials.push_back({"black", DiffuseMaterial{Spectrum(0.0f)}});
  scene.objects.push_back({"wall", make_box({-150, 50, 0}, {150, 55, 45}), 0});
  return scene;
}

TEST(FogMultipleScattering, FogInFrontOfABlackWallInItsShadow) {
  // Looking toward a low sun (15°) at the shaded face of a black wall through the
  // droplets' fog in its shadow (the rays hit it at 6–20 m), optical depths 1 and 3:
  // printed for docs/fog.md ("The field in the buildings' shadows"), where the fast
  // method reads several times the reference, the wall hiding far more of the field than
  // the sun's side. SKYLIT_FOG_MS_FULL=1 runs it.
  if (!std::getenv("SKYLIT_FOG_MS_FULL")) GTEST_SKIP() << "set SKYLIT_FOG_MS_FULL=1 to print it";
  for (double tau : {1.0, 3.0}) {
    const Scene scene = fog_in_a_walls_shadow(tau, 15);
    for (const auto& [elevation, azimuth] : {std::pair{5.0, 0.0}, {20.0, 0.0}, {5.0, 30.0}}) {
      const Ray ray{scene.camera.position, direction_from_altitude_azimuth(elevation, azimuth)};
      compare_along(scene, ray,
                    "τ " + std::to_string(tau).substr(0, 3) + ", shaded fog toward the sun, el " +
                        std::to_string(static_cast<int>(elevation)) + " az " +
                        std::to_string(static_cast<int>(azimuth)),
                    4000, 31, std::nullopt);
    }
  }
}

// A list of numbers from an environment variable ("1,3,10"), or `fallback` without it.
std::vector<double> numbers_from_environment(const char* name, std::vector<double> fallback) {
  const char* text = std::getenv(name);
  if (!text) return fallback;
  std::vector<double> out;
  for (const char* p = text; *p;) {
    char* end = nullptr;
    out.push_back(std::strtod(p, &end));
    if (end == p) break;
    p = *end ? end + 1 : end;
  }
  return out;
}

// The reference's paths per value: SKYLIT_FOG_MS_PATHS, or `fallback` without it.
int paths_from_environment(int fallback) {
  const char* text = std::getenv("SKYLIT_FOG_MS_PATHS");
  return text ? std::atoi(text) : fallback;
}

TEST(FogMultipleScattering, SurfacesFullGrid) {
  // docs/fog.md's table: every view of kStreetViews for Henyey–Greenstein fogs (g = 0.85)
  // of optical depth 1, 3 and 10, an isotropic and a droplet fog of 3, sun 30°.
  // SKYLIT_FOG_MS_PATHS (default 8000) and SKYLIT_FOG_MS_ASYMMETRY (only those fogs)
  // as for the grid below.
  if (!std::getenv("SKYLIT_FOG_MS_FULL")) GTEST_SKIP() << "set SKYLIT_FOG_MS_FULL=1 for the full grid";
  const int paths = paths_from_environment(8000);
  const std::vector<double> only = numbers_from_environment("SKYLIT_FOG_MS_ASYMMETRY", {});
  for (const auto& [tau, g] : {std::pair{1.0, 0.85}, {3.0, 0.85}, {10.0, 0.85}, {3.0, 0.0}, {3.0, 1.0}}) {
    if (!only.empty() && std::find(only.begin(), only.end(), g) == only.end()) continue;
    std::printf("[FogMS] surfaces, τ %.0f, g %.2f (1: droplets)\n", tau, g);
    compare_surfaces(fog_street(tau, 30, g), kStreetViews, 0, paths);
  }
}

TEST(FogMultipleScattering, FullGridAgainstThePathTracedReference) {
  // The droplet fit (15 µm). The reference's estimates are heavy-tailed (docs/fog.md):
  // with 200,000 paths (SKYLIT_FOG_MS_PATHS) and 5° added to the elevations, 269 of 270
  // views passed; with 2000–20,000 a small sample's low mean reads as the fast method
  // 10–35 % too bright in places.
  // Parts of the grid for measuring: SKYLIT_FOG_MS_TAUS,
  // _SUNS, _ELEVATIONS, _AZIMUTHS (comma-separated) and _ASYMMETRY (< 1: Henyey–Greenstein).
  if (!std::getenv("SKYLIT_FOG_MS_FULL")) GTEST_SKIP() << "set SKYLIT_FOG_MS_FULL=1 for the full grid";
  const int paths = paths_from_environment(20000);
  double worst = 0;
  for (double g : numbers_from_environment("SKYLIT_FOG_MS_ASYMMETRY", {1.0}))
    for (double tau : numbers_from_environment("SKYLIT_FOG_MS_TAUS", {0.1, 1.0, 3.0, 10.0, 30.0}))
      for (double sun : numbers_from_environment("SKYLIT_FOG_MS_SUNS", {10.0, 30.0, 60.0}))
        worst = std::max(worst,
                         compare(tau, sun, g, numbers_from_environment("SKYLIT_FOG_MS_ELEVATIONS", {2, 10, 30, 60, 85}),
                                 numbers_from_environment("SKYLIT_FOG_MS_AZIMUTHS", {0, 90, 150}), paths));
  std::printf("[FogMS] worst |fast/path - 1| over the grid: %.3f\n", worst);
}

}  // namespace
}  // namespace skylit
