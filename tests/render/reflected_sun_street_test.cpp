// A rough metal facade across a street from a grey wall, both in the sun's path (after
// an outside trial against Blender's Cycles, 2026-12-07): the facade's reflected sun
// lights the street and the wall across it, and the wall, so lit, lights the street in
// turn. The fast method lit the obstacles its sky-light integrals meet with the sky and
// the sun only, not with the sunlight facades reflect onto them, and read the street
// 0.75–0.86 of the path-traced reference (which Cycles matched within 2 %) near the
// wall; with the reflected sun on the obstacles' patches (render/obstacle_sky_light.h)
// 0.93–0.98.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "../test_support.h"
#include "path_luminance.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/path_integrator.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// A 60 m × 20 m × 20 m block of grey metal (aluminium's n and k at 550 nm at every
// wavelength, the aluminium preset's roughness 0.15) facing south across a 20 m street
// (ρ 0.2) to a block of the same size whose north face is grey (0.4). The sun in the
// south at 30°: the street and the north face lie in the south block's shadow; the
// facade is sunlit above 8.45 m and mirrors the sun onto the street from y = −14.6 m to
// the wall, and onto the wall below.
constexpr const char* kStreet = R"({"camera": {"position": [0, -2, 6], "look_at": [0, -20, 3]},
  "sun": {"altitude_deg": 30, "azimuth_deg": 180},
  "materials": {"metal": {"type": "cook_torrance", "roughness": 0.15, "metal": {"n": 0.96, "k": 6.69}},
                "street": {"type": "diffuse", "reflectance": 0.2}, "wall": {"type": "diffuse", "reflectance": 0.4}},
  "objects": [{"type": "plane", "material": "street", "size_m": 4000},
    {"type": "box", "material": "metal", "min": [-30, 0, 0], "max": [30, 20, 20]},
    {"type": "box", "material": "wall", "min": [-30, -40, 0], "max": [30, -20, 20]}]})";

// The street at four distances from the wall, seen straight down from 0.3 m: within 8 %
// plus three standard errors of the reference (16,000 paths: 1.9 %). Measured: 0.974,
// 0.930, 0.975, 0.964 (y −19, −17, −15, −13; 0.789, 0.779, 0.846, 0.851 before). 2 s.
TEST(ReflectedSunStreet, TheWallTheFacadeLightsLightsTheStreet) {
  testing::TempDir dir;
  const Scene scene = load_scene(dir.write("street.json", kStreet));
  const Renderer fast(scene);
  const PathIntegrator path(fast.prepared());
  for (const double y : {-19.0, -17.0, -15.0, -13.0}) {
    const Ray ray{{0, y, 0.3}, {0, 0, -1}};
    const double expected = luminance(fast.radiance(ray));
    const testing::Estimate reference = testing::path_luminance(path, ray, 16000, 23);
    std::printf("[Street] y %.0f: fast %.1f path %.1f ± %.1f cd/m2, ratio %.3f\n", y, expected, reference.mean,
                reference.standard_error, expected / reference.mean);
    EXPECT_NEAR(expected, reference.mean, 0.08 * reference.mean + 3 * reference.standard_error) << "y " << y;
  }
}

}  // namespace
}  // namespace skylit
