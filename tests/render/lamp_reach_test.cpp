// The lamps' reach (render/scene_lamps.h): the glow with shadows looked for within a
// reach, and the parts beyond it dropped or computed exactly, against the glow with
// every shadow looked for, on the Fig. 9 street.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "fig9_street.h"
#include "skylit/render/camera.h"
#include "skylit/render/scene_lamps.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

TEST(LampReach, GlowIsExactOrBelowByLessThanTheDroppedShare) {
  // Fig. 9's street is shorter than kLampReachM, so a reach of 12 m (about a lamp
  // spacing) stands in for a city's: most view rays there meet lamps beyond it. On
  // every 7th pixel centre of a 160×90 frame the glow with that reach must lie in
  // [exact·(1 − kDroppedGlowShare), exact], less the glow's own quadrature error on
  // pieces split at the reach (the closed-form tests allow 1e-3; measured here 2e-5).
  const Fig9Street street;
  const Scene& scene = street.scene;
  const RayTracer& tracer = street.tracer;
  const std::vector<const TriangleMesh*>& meshes = street.meshes;
  const FogLayer& layer = street.layer;
  const SceneLamps exact(scene.lights, tracer, meshes, &layer, std::numeric_limits<double>::infinity());
  const SceneLamps reached(scene.lights, tracer, meshes, &layer, 12.0);
  const int width = 160, height = 90;
  const ImageCamera camera(scene.camera, width, height);
  constexpr double kQuadrature = 1e-3;
  int dropped = 0, rays = 0;
  for (int i = 0; i < width * height; i += 7) {
    const Ray ray = camera.ray_through(i % width + 0.5, i / width + 0.5);
    const std::optional<Hit> hit = tracer.intersect(ray);
    const double distance = hit ? hit->t : std::numeric_limits<double>::infinity();
    const double want = luminance(exact.in_scattered(ray, distance));
    const double got = luminance(reached.in_scattered(ray, distance));
    ASSERT_GT(want, 0);
    EXPECT_LE(got, want * (1 + kQuadrature)) << "pixel " << i;
    EXPECT_GE(got, want * (1 - kDroppedGlowShare - kQuadrature)) << "pixel " << i;
    ++rays;
    if (got < want * (1 - 1e-4)) ++dropped;
  }
  // The case does drop light on many rays (else it tests nothing).
  EXPECT_GT(dropped, rays / 10);
}

}  // namespace
}  // namespace skylit
