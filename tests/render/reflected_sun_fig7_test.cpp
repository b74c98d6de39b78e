// Fig. 7 with aluminium walls (examples/fig7.json, materials.walls = "aluminium"): the
// bands method's light on the places the tower's reflected sun reaches — the sunlit
// street, the forecourt in the block's shadow, the neighbour's wall across the 8 m
// gap — against the path-traced reference (render/path_integrator.h), which carries
// the reflected sun by its glossy bounces. Each probe is a short ray straight onto the
// surface, so the air on the way is the same in both and negligible.
//
// SKYLIT_REFLECTED_SUN_HEAVY=1 takes 16 times the paths (a standard error near 0.5 %).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/path_integrator.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

struct Probe {
  const char* name;
  Vec3 point;
  Vec3 normal;
};

TEST(ReflectedSunFig7, AluminiumTowerAgainstThePathTracer) {
  const Scene scene = load_scene(std::string(SKYLIT_SOURCE_DIR) + "/examples/fig7.json", {"materials.walls=aluminium"});
  const Renderer renderer(scene);
  const PathIntegrator path(renderer.prepared());
  const BandsIntegrator& bands = renderer.bands();
  const bool heavy = std::getenv("SKYLIT_REFLECTED_SUN_HEAVY") != nullptr;
  const int paths = heavy ? 64000 : 4000;
  const Probe probes[] = {
      {"sunlit street", {-10, -35, 0.02}, {0, 0, 1}},
      {"forecourt in the block's shadow", {12, -8, 0.1}, {0, 0, 1}},
      {"wall across the gap", {34, 10, 6}, {-1, 0, 0}},
  };
  for (const Probe& probe : probes) {
    const Ray ray{probe.point + probe.normal, -probe.normal};
    const double fast = luminance(bands.radiance(ray));
    double sum = 0, squares = 0;
    for (int i = 0; i < paths; ++i) {
      CounterRandom random(7, 0, static_cast<uint64_t>(i));
      const double v = luminance(path.sample(ray, random));
      sum += v;
      squares += v * v;
    }
    const double mean = sum / paths;
    const double standard_error = std::sqrt(std::max(0.0, squares / paths - mean * mean) / paths);
    if (std::getenv("SKYLIT_REFLECTED_SUN_VERBOSE"))
      std::printf("%s: bands %.1f, path %.1f ± %.1f cd/m², reflected sun %.0f lx\n", probe.name, fast, mean,
                  standard_error,
                  illuminance(bands.facades().from_rough(probe.point, probe.normal) +
                              bands.facades().from_mirrors(probe.point, probe.normal)));
    // 10 % (the bound for this scene) plus three standard errors of the reference.
    EXPECT_NEAR(fast, mean, 0.10 * mean + 3 * standard_error) << probe.name;
  }
}

}  // namespace
}  // namespace skylit
