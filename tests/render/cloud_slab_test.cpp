// The fast method's cloud light (two-stream multiple scattering, clouds/cloud_scattering.h)
// against the path-traced reference (full multiple scattering with the droplets' phase
// function, delta tracking): a plane-parallel cloud, 200 km wide, of optical depth 5, 20
// and 50 under the sun at 30° and 60°, seen from just above (reflected light) and just
// below (transmitted light), and its albedo against the two-stream value.
//
// Tolerances: issue 13 asks for the luminances within 15 % of the reference and the
// albedo within 0.05 of the two-stream value; each bound is widened by three standard
// errors of the reference's estimate (seeds are fixed: the result does not change from
// run to run).
//
// Under the sun the reference converges slowly: 43 % of the droplets' scattering lies
// within 2° of the forward direction, and the sunlight carried by those small-angle
// scatterings reaches a path only when the path's direction happens to lie within a
// degree or two of the sun's (next-event estimation toward a directional sun through a
// spike of the phase function). The estimate is unbiased but heavy-tailed: at τ = 20, sun
// 60°, the transmitted luminance read 12.4, 15.1, 15.4 and 20.4 kcd/m² after 1, 16, 256
// and 1024 thousand paths (with the Russian roulette of before 228d9a4, which made it
// worse; fast method: 20.7). So the sunlit matrix (DISABLED_SunAt30,
// DISABLED_SunAt60; 100,000 paths per value, about ten minutes each, recorded in
// docs/clouds.md) is run by hand; CI checks the sky-lit slab (uniform radiance above and
// below, no sun: the reference's sky is drawn by multiple importance sampling, which
// tames the spike), the same two-stream fields that carry the sun's light.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skylit/clouds/cloud_scattering.h"
#include "skylit/clouds/cloud_two_stream.h"
#include "skylit/render/renderer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

constexpr double kBase = 1500;       // m, the slab's bottom
constexpr double kGap = 10;          // m, between the viewer and the slab's face
constexpr double kSunAzimuth = 180;  // the sun in the south

Scene slab_scene(double optical_depth, double sun_altitude_deg, bool from_above) {
  CloudShape slab;
  slab.semi_axis_a = slab.semi_axis_b = 100000;
  slab.falloff_exponent = 0;  // (1 − r²)^0: the same thickness everywhere
  slab.max_thickness = optical_depth / slab.extinction;
  slab.altitude = kBase + 0.5 * slab.max_thickness;
  Scene scene;
  const double z = from_above ? kBase + slab.max_thickness + kGap : kBase - kGap;
  scene.camera = Camera{{0, 0, z}, {0, 1, z}, {0, 0, 1}, 50.0};
  scene.sun = Sun{sun_altitude_deg, kSunAzimuth};
  scene.clouds.push_back(slab);
  return scene;
}

struct Estimate {
  double mean = 0, standard_error = 0;
};

// The mean and standard error of n paths' `value`; `ray_of(i)` gives path i's ray.
template <typename RayOf, typename Value>
Estimate estimate(const PathIntegrator& path, int n, RayOf&& ray_of, Value&& value) {
  double sum = 0, squares = 0;
  for (int i = 0; i < n; ++i) {
    CounterRandom random(5, 0, static_cast<uint64_t>(i));
    const Ray ray = ray_of(i, random);
    const double v = value(path.sample(ray, random));
    sum += v;
    squares += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1))};
}

// A view at `zenith_deg` from straight down (from above) or straight up (from below),
// leaning toward the sun's azimuth (positive) or away from it.
Vec3 view(bool from_above, double zenith_deg) {
  const double s = std::sin(radians(zenith_deg)), c = std::cos(radians(zenith_deg));
  return {0, -s, from_above ? -c : c};  // the sun is in the south (−y)
}

struct Comparison {
  double fast, reference, standard_error;
};

Comparison compare_view(const Renderer& fast, const PathIntegrator& path, const Ray& ray, int paths) {
  const Estimate e = estimate(
      path, paths, [&](int, CounterRandom&) { return ray; }, [](const Radiance& r) { return luminance(r); });
  return {luminance(fast.radiance(ray)), e.mean, e.standard_error};
}

// The slab's albedo from the reference: the flux leaving its top (π × the mean luminance
// of cosine-weighted downward views) over the flux onto it (the sun's and the sky's), and
// the two-stream's for the same light: the sun's, the sky's from above and the ground's
// from below, as the fast method lights its clouds (clouds/clouds_in_sky.cpp).
struct Albedo {
  double reference, standard_error, two_stream;
};

Albedo compare_albedo(const Renderer& fast, const PathIntegrator& path, double optical_depth, int paths) {
  const SkyModel& sky = fast.sky();
  const CloudShape& slab = fast.prepared().clouds()->layer().clouds()[0].shape();
  const Vec3 eye{0, 0, slab.altitude + 0.5 * slab.max_thickness + kGap};
  const Estimate up = estimate(
      path, paths,
      [&](int, CounterRandom& random) {
        const double u1 = random.uniform(), u2 = random.uniform();
        const double c = std::sqrt(u1), s = std::sqrt(1 - u1), phi = 2 * kPi * u2;
        return Ray{eye, {s * std::cos(phi), s * std::sin(phi), -c}};
      },
      [](const Radiance& r) { return kPi * luminance(r); });
  const double mu0 = fast.prepared().to_sun().z;
  const double sun = illuminance(sky.direct_sun(slab.altitude));
  const double above = illuminance(sky.sky_irradiance({0, 0, 1})), below = illuminance(sky.sky_irradiance({0, 0, -1}));
  const DeltaScaling scaling(cloud_mean_cosine());
  const double depth = scaling.scaled_depth(optical_depth), g = scaling.asymmetry;
  auto leaving_top = [](const EddingtonField& f) { return kPi * (f.mean - 2.0 / 3.0 * f.flux); };
  const double two_stream_up = eddington_sun_albedo(depth, g, mu0) * mu0 * sun +
                               leaving_top(eddington_diffuse_field(depth, g, 0, true)) * above +
                               leaving_top(eddington_diffuse_field(depth, g, 0, false)) * below;
  const double onto = mu0 * sun + above;
  return {up.mean / onto, up.standard_error / onto, two_stream_up / onto};
}

void run_sunlit(double sun, int paths) {
  for (double tau : {5.0, 20.0, 50.0}) {
    for (bool from_above : {true, false}) {
      const Scene scene = slab_scene(tau, sun, from_above);
      const Renderer fast(scene);
      const PathIntegrator path(fast.prepared());
      const Ray ray{scene.camera.position, view(from_above, 0)};
      const Comparison c = compare_view(fast, path, ray, paths);
      std::printf("tau %2.0f sun %2.0f %s: fast %8.1f path %8.1f ± %6.1f cd/m2  fast/path %.3f\n", tau, sun,
                  from_above ? "reflected  " : "transmitted", c.fast, c.reference, c.standard_error,
                  c.fast / c.reference);
      EXPECT_NEAR(c.fast, c.reference, 0.15 * c.reference + 3 * c.standard_error)
          << "τ " << tau << " sun " << sun << (from_above ? " reflected" : " transmitted");
      if (from_above) {
        const Albedo a = compare_albedo(fast, path, tau, paths);
        std::printf("tau %2.0f sun %2.0f albedo: path %.3f ± %.3f  two-stream %.3f\n", tau, sun, a.reference,
                    a.standard_error, a.two_stream);
        EXPECT_NEAR(a.reference, a.two_stream, 0.05 + 3 * a.standard_error) << "τ " << tau << " sun " << sun;
      }
    }
  }
}

TEST(CloudSlab, DISABLED_SunAt30) { run_sunlit(30, 100000); }
TEST(CloudSlab, DISABLED_SunAt60) { run_sunlit(60, 100000); }

TEST(CloudSlab, SkyLitMatchesPathTracedReference) {
  // Radiance 1 from above the horizon, 0.25 from below (a dark ground), no sun: the fast
  // method's cloud light with the same irradiances (π and π/4) against the reference,
  // straight up and straight down, the sky seen through the slab added to the fast
  // method's light as the reference sees it; and the flux leaving the top over the flux
  // onto it against the two-stream's. 1500 paths per value: standard errors 1–2 %.
  const Spectrum above(1.0f), below(0.25f);
  const DeltaScaling scaling(cloud_mean_cosine());
  for (double tau : {5.0, 20.0, 50.0}) {
    const Scene scene = slab_scene(tau, 60, false);
    const PreparedScene prepared(scene);
    const PathIntegrator path(prepared, TestEnvironment{above, below});
    const Cloud& slab = prepared.clouds()->layer().clouds()[0];
    CloudLighting light;
    light.sun = Spectrum(0.0f);
    light.sky_from_above = above * static_cast<float>(kPi);
    light.sky_from_below = below * static_cast<float>(kPi);
    const double top = slab.shape().altitude + 0.5 * slab.shape().max_thickness;
    for (bool from_above : {true, false}) {
      const Ray ray{{0, 0, from_above ? top + kGap : kBase - kGap}, view(from_above, 0)};
      const CloudScattering fast = slab.scatter(ray.origin, ray.direction, 0, 1e7, light);
      const double fast_value =
          (fast.in_scattered + (from_above ? below : above) * static_cast<float>(fast.transmittance))[0];
      const Estimate e = estimate(
          path, 1500, [&](int, CounterRandom&) { return ray; }, [](const Radiance& r) { return double(r[0]); });
      std::printf("sky-lit tau %2.0f %s: fast %.4f path %.4f ± %.4f  fast/path %.3f\n", tau,
                  from_above ? "reflected  " : "transmitted", fast_value, e.mean, e.standard_error,
                  fast_value / e.mean);
      EXPECT_NEAR(fast_value, e.mean, 0.15 * e.mean + 3 * e.standard_error) << "τ " << tau << from_above;
    }
    // Albedo: π × the mean radiance of cosine-weighted downward views over the flux onto
    // the top (π × 1), against the two-stream's.
    const Estimate up = estimate(
        path, 1500,
        [&](int, CounterRandom& random) {
          const double u1 = random.uniform(), u2 = random.uniform();
          const double c = std::sqrt(u1), s = std::sqrt(1 - u1), phi = 2 * kPi * u2;
          return Ray{{0, 0, top + kGap}, {s * std::cos(phi), s * std::sin(phi), -c}};
        },
        [](const Radiance& r) { return double(r[0]); });
    const double depth = scaling.scaled_depth(tau), g = scaling.asymmetry;
    auto leaving_top = [](const EddingtonField& f) { return kPi * (f.mean - 2.0 / 3.0 * f.flux); };
    const double two_stream = (leaving_top(eddington_diffuse_field(depth, g, 0, true)) * kPi +
                               leaving_top(eddington_diffuse_field(depth, g, 0, false)) * kPi * 0.25) /
                              kPi;
    std::printf("sky-lit tau %2.0f albedo: path %.3f ± %.3f  two-stream %.3f\n", tau, up.mean, up.standard_error,
                two_stream);
    EXPECT_NEAR(up.mean, two_stream, 0.05 + 3 * up.standard_error) << "τ " << tau;
  }
}

}  // namespace
}  // namespace skylit
