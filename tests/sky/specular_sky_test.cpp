// Specular sky light by the paper's adaptive band search (§4.2) against a dense
// quadrature of the same sky, for a grid of normals, views and roughness values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skylit/material/optical_constants.h"
#include "skylit/material/reflection.h"
#include "skylit/sky/sky_light.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// ∫ f_s(l, v)(n·l) L(l) dω over the whole sphere by the midpoint rule on a 400 × 800
// grid in (θ, φ) (0.45° cells): the brute-force reference, in luminance.
double dense_specular_luminance(const SkyModel& sky, const Material& m, const Vec3& n, const Vec3& v) {
  constexpr int kTheta = 400, kPhi = 800;
  Radiance sum;
  for (int i = 0; i < kTheta; ++i) {
    const double theta = kPi * (i + 0.5) / kTheta;
    const double weight = std::sin(theta) * (kPi / kTheta) * (2 * kPi / kPhi);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kPhi;
      const Vec3 l{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      if (dot(n, l) <= 0) continue;
      const double w = specular_weight(m, n, l, v);
      if (w <= 0) continue;
      sum += specular_reflection(m, n, l, v).reflect(sky.sky_radiance_near_ground(l), weight);
    }
  }
  return luminance(sum);
}

TEST(SpecularSky, AdaptiveBandSearchMatchesADenseQuadrature) {
  const Atmosphere atmosphere{AtmosphereSettings{}};
  const SkyModel sky(atmosphere, direction_from_altitude_azimuth(30, 150), 1.6);
  RayTracer open_field;
  open_field.commit();
  const SkyLight light(sky, open_field, [](const Ray&, const Hit&, double) { return Radiance(0.0f); });
  struct Case {
    Vec3 normal;
    double view_from_normal_deg, view_azimuth_deg;
  };
  // Walls facing south, east and north-west, a roof; views from head-on to 70°.
  const Vec3 south{0, -1, 0}, east{1, 0, 0}, north_west = normalize(Vec3{-1, 1, 0}), up{0, 0, 1};
  double worst = 0;
  uint64_t total_rays = 0;
  int cases = 0;
  for (double roughness : {0.1, 0.15, 0.3}) {
    const Material aluminium = CookTorranceMaterial(aluminium_ior(), roughness);
    for (const Vec3& n : {south, east, north_west, up}) {
      for (double view : {0.0, 35.0, 70.0}) {
        // A view direction `view` degrees from the normal, tilted toward the ground
        // (the observer below) or sideways.
        const Vec3 side = length(cross(n, up)) > 0.5 ? normalize(cross(n, up)) : Vec3{1, 0, 0};
        const Vec3 down = normalize(cross(side, n));
        for (const Vec3& tilt : {side, down}) {
          if (view == 0.0 && tilt == down) continue;  // the same view as sideways
          const Vec3 v = normalize(n * std::cos(radians(view)) + tilt * std::sin(radians(view)));
          const uint64_t rays_before = open_field.rays_traced();
          const double fast = luminance(light.specular_radiance({0, 0, 10}, n, v, aluminium));
          const uint64_t rays = open_field.rays_traced() - rays_before;
          const double dense = dense_specular_luminance(sky, aluminium, n, v);
          const double error = std::abs(fast - dense) / dense;
          total_rays += rays;
          ++cases;
          worst = std::max(worst, error);
          // 2 % (the requirement at the default band counts and ε).
          EXPECT_LT(error, 0.02) << "m " << roughness << " n " << n.x << "," << n.y << "," << n.z << " view " << view
                                 << " fast " << fast << " dense " << dense;
        }
      }
    }
  }
  std::printf("[ specular ] worst relative error against the dense quadrature: %.4f; %.0f rays a point on average\n",
              worst, static_cast<double>(total_rays) / cases);
}

}  // namespace
}  // namespace skylit
