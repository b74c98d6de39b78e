// SceneLamps::illuminance_at_least, which the sky-light cache weighs its corners against
// (CachedSkyLight::other_lx, render/image_loop.cpp): the lamps' illuminance from the intensity maps,
// against irradiance_on's from the luminaires' own tables with every lamp tested for
// occlusion, at the surface points a view of the Fig. 9 street sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "fig9_street.h"
#include "skylit/render/camera.h"
#include "skylit/render/scene_lamps.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

TEST(LampsIlluminance, AtLeastIsTheLampsIlluminanceUntilItIsEnough) {
  const Fig9Street street;
  const Scene& scene = street.scene;
  ASSERT_TRUE(street.layer.is_grey());  // else illuminance_at_least is a lower bound only
  const SceneLamps lamps(scene.lights, street.tracer, street.meshes, &street.layer);
  const int width = 160, height = 90;
  const ImageCamera camera(scene.camera, width, height);
  // The intensity maps differ from the luminaires' tables by interpolation, by 1.1 % of
  // the peak intensity at worst (where a cut-off bends the table, docs/lights.md): each
  // lamp may be off by 1.2 % of its peak over d². A lamp lost to a wrong occlusion test
  // or direction would take a share of tens of per cent.
  constexpr double kMapTolerance = 0.012;
  std::vector<double> peak_cd;
  for (const SceneLight& light : scene.lights) {
    double peak = 0;
    for (double c = 0; c < 360; c += 2)
      for (double gamma = 0; gamma <= 180; gamma += 1)
        peak = std::max(peak, light.luminaire.distribution().candela(c, gamma));
    peak_cd.push_back(peak * light.luminaire.tilt_multiplier());
  }
  int lit = 0, shadowed = 0;
  for (int i = 0; i < width * height; i += 13) {
    const Ray ray = camera.ray_through(i % width + 0.5, i / width + 0.5);
    const std::optional<Hit> hit = street.tracer.intersect(ray);
    if (!hit) continue;
    Vec3 normal = hit->geometric_normal;
    if (dot(normal, ray.direction) > 0) normal = -normal;
    const SurfacePoint point{ray.origin + hit->t * ray.direction, normal, hit->t, 0};
    double tolerance_lx = 0;
    for (size_t k = 0; k < scene.lights.size(); ++k) {
      const Vec3 to_lamp = scene.lights[k].luminaire.position() - point.position;
      tolerance_lx += kMapTolerance * peak_cd[k] / dot(to_lamp, to_lamp);
    }
    const double exact_lx = illuminance(lamps.irradiance_on(point));
    const double all_lx = lamps.illuminance_at_least(point, std::numeric_limits<double>::infinity());
    EXPECT_NEAR(all_lx, exact_lx, tolerance_lx) << "pixel " << i;
    // Asked for half of it: at least that much (or all there is), never more than all.
    const double half_lx = lamps.illuminance_at_least(point, 0.5 * exact_lx);
    EXPECT_GE(half_lx, 0.5 * exact_lx - tolerance_lx) << "pixel " << i;
    EXPECT_LE(half_lx, all_lx * (1 + 1e-12)) << "pixel " << i;
    (exact_lx > 0 ? lit : shadowed)++;
  }
  EXPECT_GT(lit, 200);
}

}  // namespace
}  // namespace skylit
