// The measurement behind SkyLight's default band and segment counts: the sky view
// factor in street canyons against the closed form, for several counts. Prints the
// table that docs/sky-light.md records.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skylit/geometry/primitives.h"
#include "skylit/sky/sky_light.h"

namespace skylit {
namespace {

double worst_canyon_error(const SkyModel& sky, const std::vector<SkyElement>& elements) {
  double worst = 0;
  for (bool along_x : {false, true}) {
    for (double h_over_w : {0.25, 0.5, 1.0, 2.0, 3.0}) {
      RayTracer tracer;
      const double w = 20, h = h_over_w * w, l = 2000;
      if (along_x) {
        tracer.add_mesh(make_box({-l, w / 2, 0}, {l, w / 2 + 10, h}));
        tracer.add_mesh(make_box({-l, -w / 2 - 10, 0}, {l, -w / 2, h}));
      } else {
        tracer.add_mesh(make_box({w / 2, -l, 0}, {w / 2 + 10, l, h}));
        tracer.add_mesh(make_box({-w / 2 - 10, -l, 0}, {-w / 2, l, h}));
      }
      tracer.commit();
      const SkyLight light(
          sky, tracer, [](const Ray&, const Hit&, double) { return Radiance(0.0f); }, elements);
      // Across the floor, not only on the centre line: the view factor of a point at
      // x from the centre is (sin φ₁ + sin φ₂)/2 with tan φ = (w/2 ∓ x)/h.
      for (double x : {0.0, 3.0, 7.0}) {
        const Vec3 p = along_x ? Vec3{0, x, 0} : Vec3{x, 0, 0};
        const double f = light.sky_view_factor(p, {0, 0, 1});
        const double expected = 0.5 * (std::sin(std::atan((w / 2 - x) / h)) + std::sin(std::atan((w / 2 + x) / h)));
        worst = std::max(worst, std::abs(f - expected));
      }
    }
  }
  return worst;
}

TEST(BandCountStudy, CanyonViewFactorErrorByCounts) {
  const Atmosphere atmosphere{AtmosphereSettings{}};
  const SkyModel sky(atmosphere, direction_from_altitude_azimuth(40, 150), 1.6);
  std::printf("[ band count ] worst |view factor − closed form| over canyons h/w 0.25–3, both orientations\n");
  std::printf("[ band count ] bands  segments  rays/point  worst error\n");
  for (int bands : {16, 32}) {
    for (int segments : {16, 32}) {
      const double e = worst_canyon_error(sky, BandSources(bands, segments).elements());
      std::printf("[ band count ] %5d  %8d  %10d  %.4f\n", bands, segments, bands * segments, e);
    }
  }
  for (int count : {256, 512, 1024, 2048}) {
    std::printf("[ band count ] fibonacci %4d  %10d  %.4f\n", count, count / 2,
                worst_canyon_error(sky, fibonacci_sphere(count)));
  }
  const double chosen = worst_canyon_error(sky, fibonacci_sphere(SkyLight::kDefaultDirections));
  EXPECT_LT(chosen, 0.012);  // measured 0.0102: docs/sky-light.md
}

}  // namespace
}  // namespace skylit
