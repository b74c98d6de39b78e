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
// Under the sun the reference once converged slowly: 43 % of the droplets' scattering
// lies within 2° of forward, and the sunlight carried by small-angle scatterings reached
// a path only when its direction happened to lie within a degree or two of the sun's. At
// τ = 20, sun 60°, the transmitted luminance read 12.4, 15.1, 15.4 and 20.4 kcd/m² after
// 1, 16, 256 and 1024 thousand paths. The reference's spike paths (render/
// path_integrator.h) and its ratio tracking of the clouds' transmittance
// (clouds/cloud_tracking.cpp) took the heavy tail away, and the balance of the slab's
// energy below checks that they are unbiased. The sky-lit slab (uniform radiance above
// and below, no sun) checks the same two-stream fields without the spike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <tbb/parallel_for.h>

#include "skylit/clouds/cloud_scattering.h"
#include "skylit/clouds/cloud_two_stream.h"
#include "skylit/media/phase_sampler.h"
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

// The mean and standard error of n samples, `sample(i, random)` drawing sample i from
// its own counter-based stream. Samples run in parallel and are summed in order: the
// same result on any number of threads.
template <typename Sample>
Estimate mean_of(int n, Sample&& sample) {
  std::vector<double> values(static_cast<size_t>(n));
  tbb::parallel_for(0, n, [&](int i) {
    CounterRandom random(5, 0, static_cast<uint64_t>(i));
    values[static_cast<size_t>(i)] = sample(i, random);
  });
  double sum = 0, squares = 0;
  for (const double v : values) {
    sum += v;
    squares += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1))};
}

// The mean and standard error of n paths' `value`; `ray_of(i)` gives path i's ray.
template <typename RayOf, typename Value>
Estimate estimate(const PathIntegrator& path, int n, RayOf&& ray_of, Value&& value) {
  return mean_of(n, [&](int i, CounterRandom& random) {
    const Ray ray = ray_of(i, random);
    return value(path.sample(ray, random));
  });
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

// The luminous flux leaving a face of the slab: the luminance of views from `eye`
// toward it (downward from above, upward from below) times their cosine, over the
// density they are drawn with. From below the sun's aureole through the droplets' spike
// is a peak that cosine-weighted views alone meet rarely (a heavy tail: a slab of optical
// depth 2 read 0.66–1.07 of its energy with 2,000–32,000 of them), so there half the
// views are drawn from the droplets' phase function within 5° of the sun, and each is
// weighed by the mixture's density.
Estimate flux_leaving(const PathIntegrator& path, const Vec3& eye, bool from_above, const Vec3& to_sun, int paths) {
  static const PhaseSampler droplets([](double c) { return cloud_phase(c); });
  static const PhaseSampler::Cone cone = droplets.cone(radians(5.0));
  const double toward_sun = from_above ? 0.0 : 0.5;
  return mean_of(paths, [&](int, CounterRandom& random) {
    const double u0 = random.uniform(), u1 = random.uniform(), u2 = random.uniform();
    Vec3 d;
    if (u0 < toward_sun) {
      d = droplets.sample_within(cone, to_sun, u1, u2).direction;
    } else {
      const double c = std::sqrt(u1), s = std::sqrt(1 - u1), phi = 2 * kPi * u2;
      d = {s * std::cos(phi), s * std::sin(phi), from_above ? -c : c};
    }
    const double cosine = from_above ? -d.z : d.z;
    if (cosine <= 0) return 0.0;
    const double density = (1 - toward_sun) * cosine / kPi + toward_sun * droplets.pdf_within(cone, dot(to_sun, d));
    return luminance(path.sample(Ray{eye, d}, random)) * cosine / density;
  });
}

// The slab's albedo from the reference (the flux leaving its top over the flux onto it:
// the sun's and the sky's), and the two-stream's for the same light: the sun's, the
// sky's from above and the ground's from below, as the fast method lights its clouds
// (clouds/clouds_in_sky.cpp). And the reference's energy balance: a non-absorbing slab
// sends out through its faces what comes in through them.
struct Albedo {
  double reference, standard_error, two_stream;
  double out_over_in, out_over_in_error;
};

Albedo compare_albedo(const Renderer& fast, const PathIntegrator& path, double optical_depth, int paths) {
  const SkyModel& sky = fast.sky();
  const CloudShape& slab = fast.prepared().clouds()->layer().clouds()[0].shape();
  const double top = slab.altitude + 0.5 * slab.max_thickness;
  const Vec3& to_sun = fast.prepared().to_sun();
  const Estimate up = flux_leaving(path, {0, 0, top + kGap}, true, to_sun, paths);
  const Estimate down = flux_leaving(path, {0, 0, kBase - kGap}, false, to_sun, paths);
  const double mu0 = to_sun.z;
  const double sun = illuminance(sky.direct_sun(top));
  const double above = illuminance(sky.sky_irradiance({0, 0, 1})), below = illuminance(sky.sky_irradiance({0, 0, -1}));
  const DeltaScaling scaling(cloud_mean_cosine());
  const double depth = scaling.scaled_depth(optical_depth), g = scaling.asymmetry;
  auto leaving_top = [](const EddingtonField& f) { return kPi * (f.mean - 2.0 / 3.0 * f.flux); };
  const double two_stream_up = eddington_sun_albedo(depth, g, mu0) * mu0 * sun +
                               leaving_top(eddington_diffuse_field(depth, g, 0, true)) * above +
                               leaving_top(eddington_diffuse_field(depth, g, 0, false)) * below;
  const double onto = mu0 * sun + above;
  // Out: both faces' flux (from below the sunlight let through unscattered too: the
  // views drawn around the sun meet its disc). In: the sun, the sky above, the ground's
  // light from below.
  const double out = up.mean + down.mean, in = onto + below;
  return {up.mean / onto, up.standard_error / onto, two_stream_up / onto, out / in,
          std::hypot(up.standard_error, down.standard_error) / in};
}

// Energy: the flux out over the flux in, within 3 % plus three standard errors.
// Measured at 40,000 paths (2026-12-04): 0.995–1.021 ± 0.012–0.018 for the six slabs,
// within 1.2 standard errors of 1. The reference lights each scattering point with the
// sun's irradiance at its own height (the air inside the slab takes a fraction of a per
// cent) and reads the sky and the ground from tables: the 3 % covers those. A biased
// estimator of the multiple scattering (a weight missing from either strategy of the
// sun's spike paths, render/path_integrator.h) shows as tens of per cent, and so did
// the heavy tail without them (a slab of optical depth 2 read 0.82 at 8,000 paths).
constexpr double kEnergyTolerance = 0.03;

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
        std::printf("tau %2.0f sun %2.0f albedo: path %.3f ± %.3f  two-stream %.3f; out / in %.4f ± %.4f\n", tau, sun,
                    a.reference, a.standard_error, a.two_stream, a.out_over_in, a.out_over_in_error);
        EXPECT_NEAR(a.reference, a.two_stream, 0.05 + 3 * a.standard_error) << "τ " << tau << " sun " << sun;
        EXPECT_NEAR(a.out_over_in, 1.0, kEnergyTolerance + 3 * a.out_over_in_error) << "τ " << tau << " sun " << sun;
      }
    }
  }
}

// Paths per value: 10,000 in CI (standard errors 1–6 %; both suns about 40 s on two
// cores), more by hand with SKYLIT_CLOUD_SLAB_PATHS.
int sunlit_paths() {
  const char* paths = std::getenv("SKYLIT_CLOUD_SLAB_PATHS");
  return paths ? std::max(100, std::atoi(paths)) : 10000;
}
TEST(CloudSlab, SunAt30MatchesPathTracedReference) { run_sunlit(30, sunlit_paths()); }
TEST(CloudSlab, SunAt60MatchesPathTracedReference) { run_sunlit(60, sunlit_paths()); }

TEST(CloudSlab, ThinSunlitSlabConservesEnergy) {
  // The reference's spike paths and ratio tracking (cheap enough to run under the
  // sanitizers too): a slab of optical depth 2 under the sun at 45°, its energy balance
  // as in run_sunlit, 4,000 paths per face (standard error about 2.5 %; without the spike
  // paths 0.82 ± 0.03 at 8,000, 0.95 ± 0.05 at 32,000; with them 1.035 ± 0.025 and
  // 1.014 ± 0.013).
  const Scene scene = slab_scene(2, 45, true);
  const Renderer fast(scene);
  const PathIntegrator path(fast.prepared());
  const Albedo a = compare_albedo(fast, path, 2, 4000);
  std::printf("tau 2 sun 45: out / in %.4f ± %.4f\n", a.out_over_in, a.out_over_in_error);
  EXPECT_NEAR(a.out_over_in, 1.0, kEnergyTolerance + 3 * a.out_over_in_error);
}

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
