// A road of the CIE class R3 in a rendered night scene (material/road_reflection.h
// through render/scene_lamps.h): the luminance the renderer gives at road points seen
// from 1.5 m high and 80 m back is the road-lighting designer's L = I r(β, tan γ) / h²,
// with r typed from the published table.
#include <gtest/gtest.h>

#include <cmath>

#include "skylit/geometry/primitives.h"
#include "skylit/lights/lamp_spectrum.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

Scene road_at_night(const Material& road) {
  Scene scene;
  scene.camera = Camera{{0, -80, 1.5}, {0, 0, 0}, {0, 0, 1}, 30.0};
  scene.sun = Sun{-40, 180};  // no twilight
  scene.materials.push_back({"road", road});
  scene.objects.push_back({"road", make_ground_plane({0, 0, 0}, 2000), 0});
  LampSpectrumSettings led;
  scene.lights.push_back(
      {"lamp", Luminaire({0, 0, 6}, IntensityDistribution::isotropic(1000.0)), lamp_spectrum_per_candela(led)});
  scene.render = RenderSettings{16, 16, std::nullopt, 1};
  return scene;
}

double luminance_seen_at(const Renderer& renderer, const Vec3& eye, double y) {
  return luminance(renderer.radiance(Ray{eye, normalize(Vec3{0, y, 0} - eye)}));
}

TEST(RoadRender, R3RoadLuminanceIsTheRTableNearGrazingAndQ0FromAbove) {
  // Points on the line below the lamp (6 m up), tan γ = |y|/6 at table nodes. Beyond
  // the lamp (y > 0) it stands between observer and point, β = 180°; before it (y < 0)
  // beyond the point, β = 0. Views are at most 1.2° above the road, inside the tables'
  // range (no blend). Tolerance 2 %: the clear air's extinction over the ≤ 95 m view
  // (~0.1–0.5 %), the lamp's intensity map (exact for an isotropic lamp) and the night
  // sky (bounded below).
  const Scene scene = road_at_night(RoadMaterial(RoadReflectionTable::standard("R3"), 0.07));
  const Renderer renderer(scene);
  const Vec3 eye{0, -80, 1.5};
  struct Point {
    double y, r;  // r × 10⁴, CIE R3
  };
  const Point points[] = {{0, 294}, {3, 194}, {6, 100}, {12, 38}, {-3, 344}, {-6, 362}, {-12, 326}};
  for (const Point& p : points) {
    const double expected = 1000 * p.r * 1e-4 / 36;
    EXPECT_NEAR(luminance_seen_at(renderer, eye, p.y), expected, 0.02 * expected) << "y = " << p.y;
  }
  // The Lambertian asphalt preset (ρ = 0.08) seen there is far darker before the lamp,
  // where R3's forward peak lies: the gap issue 18 measured on a lit street.
  const Scene asphalt = road_at_night(DiffuseMaterial{Spectrum(0.08f)});
  const Renderer lambertian(asphalt);
  EXPECT_LT(2 * luminance_seen_at(lambertian, eye, -6), luminance_seen_at(renderer, eye, -6));

  // From 10 m straight above a point 3 m beside the lamp's foot (α = 90°) the road is
  // Lambertian with f = Q0: L = Q0 E, E = I h / d³. Tolerance 2 % as above.
  const double d = std::hypot(3.0, 6.0);
  const double diffuse = 0.07 * 1000 * 6 / (d * d * d);
  EXPECT_NEAR(luminance(renderer.radiance(Ray{{3, 0, 10}, {0, 0, -1}})), diffuse, 0.02 * diffuse);
}

}  // namespace
}  // namespace skylit
