// The sunlight that the fog in the buildings' shadows does not scatter toward a surface
// (media/fog_shadowed_sunlight.h), against computations that do not share its method:
// the closed form of a level ray through a wall's shadow in a uniform slab, and the
// field's own single scattering (FogDiffuseField::radiance less radiance_without_sun,
// from its discrete-ordinates solution) where the whole layer lies in shadow.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "fog_slab.h"
#include "skylit/atmosphere/seen_sun.h"
#include "skylit/core/angles.h"
#include "skylit/geometry/primitives.h"
#include "skylit/media/fog_shadowed_sunlight.h"
#include "skylit/media/fog_sky_light.h"

namespace skylit {
namespace {

constexpr double kTop = 100;

// A uniform droplet fog slab under a sun in the north (azimuth 0), with one mesh that
// casts the shadow and a tracer holding it.
struct ShadowedFog {
  Atmosphere atmosphere;
  SkyModel sky;
  FogLayer layer;
  FogSkyLight sky_light;
  TriangleMesh mesh;
  RayTracer tracer;
  SunShadowVolumes shadows;
  Spectrum sun_above_fog;
  FogShadowedSunlight shadowed;

  ShadowedFog(double optical_depth, double sun_altitude_deg, TriangleMesh caster, double wavelength_exponent = 0)
      : atmosphere(AtmosphereSettings{}),
        sky(atmosphere, direction_from_altitude_azimuth(sun_altitude_deg, 0), 1.6),
        layer(fog(optical_depth, wavelength_exponent)),
        sky_light(layer, sky),
        mesh(std::move(caster)),
        tracer(traced(mesh)),
        shadows(std::vector<const TriangleMesh*>{&mesh}, sky.to_sun()),
        sun_above_fog(sky.direct_sun(kTop).spectrum()),
        shadowed(layer, *sky_light.diffuse_field(), shadows, tracer, sky.to_sun(), sun_above_fog) {}

  static FogSettings fog(double optical_depth, double wavelength_exponent) {
    FogSettings f = testing::uniform_fog_slab(optical_depth, kTop);
    f.multiple_scattering = true;
    f.wavelength_exponent = wavelength_exponent;
    return f;
  }
  static RayTracer traced(const TriangleMesh& mesh) {
    RayTracer t;
    t.add_mesh(mesh);
    t.commit();
    return t;
  }
};

TEST(FogShadowedSunlight, ALevelRayThroughAWallsShadowHasTheClosedForm) {
  // A wall along x (−100 … 100 m, 5 m thick at y 50–55, 60 m high) and the sun in the
  // north at 30°: its shadow is the prism below the plane from the wall's top down at
  // 30° toward −y, between x = −100 and 100. A level ray at 10 m, 20 m south of the
  // wall, from x = 40 toward +x lies in shadow over its first 60 m (to x = 100) and in
  // the sun beyond; toward −x over 140 m. In a uniform slab of density 1 the missing
  // radiance over [0, L] is, per bin of extinction σ,
  // ω₀(1 − f)p'(cos Θ)·E·e^(−s σ (top − z)/sin 30°)·(1 − e^(−s σ L))/s,
  // s = 1 − ω₀f: the function's steps take the sunlight at their middle, exact here.
  // A white fog and one whose extinction falls with wavelength (b = 1.3, every bin its
  // own σ).
  for (double b : {0.0, 1.3}) {
    const ShadowedFog fog(1.0, 30.0, make_box({-100, 50, 0}, {100, 55, 60}), b);
    const FogDiffuseField& field = *fog.sky_light.diffuse_field();
    const auto& sigma = fog.layer.unit_density_extinction_bins();
    const Vec3 point{40, 30, 10}, along{1, 0, 0};
    const Vec3 to_sun = normalize(fog.sky.to_sun());
    const double s = field.sun_depth_scale();
    auto expected = [&](const Vec3& direction, double length, int k) {
      const double phase = (1 - field.forward_fraction()) * field.smooth_phase(dot(direction, to_sun));
      const double sg = s * sigma[static_cast<size_t>(k)];
      return field.single_scattering_albedo() * phase * std::exp(-sg * (kTop - point.z) / to_sun.z) *
             -std::expm1(-sg * length) / s * fog.sun_above_fog[k];
    };
    const Spectrum whole = fog.shadowed.missing_radiance(point, along, std::numeric_limits<double>::infinity());
    const Spectrum half = fog.shadowed.missing_radiance(point, along, 30.0);  // only up to a surface
    const Spectrum back = fog.shadowed.missing_radiance(point, -along, std::numeric_limits<double>::infinity());
    for (int k = 0; k < kSpectralBins; k += 5) {
      ASSERT_GT(fog.sun_above_fog[k], 0.0f);
      EXPECT_NEAR(whole[k], expected(along, 60.0, k), 1e-4 * expected(along, 60.0, k)) << "b " << b << ", bin " << k;
      EXPECT_NEAR(half[k], expected(along, 30.0, k), 1e-4 * expected(along, 30.0, k)) << "b " << b << ", bin " << k;
      EXPECT_NEAR(back[k], expected(-along, 140.0, k), 1e-4 * expected(-along, 140.0, k)) << "b " << b << ", bin " << k;
    }
    if (b > 0) {  // the bins do differ in more than the sunlight
      EXPECT_GT(std::abs(whole[0] / whole[39] - fog.sun_above_fog[0] / fog.sun_above_fog[39]), 1e-3);
    }
    // A ray in the open sun misses nothing.
    const Spectrum open = fog.shadowed.missing_radiance(Vec3{40, -200, 10}, along, 500.0);
    EXPECT_EQ(open.max_value(), 0.0f);
  }
}

TEST(FogShadowedSunlight, WithTheWholeLayerInShadowTheFieldsSingleScatteringIsMissing) {
  // A roof over everything just above the layer: no fog is sunlit, and what a point at
  // the ground facing up misses is all the sunlight the open field's fog scatters
  // toward it once, ∫ (L − L_without_sun) cos dω with the field's own radiances (its
  // discrete ordinates and Fourier terms in azimuth), by a dense midpoint rule. Within
  // 1 % (0.1 % measured, with the renderer's 128 directions): the field's terms stop at
  // 2N = 16 in azimuth and its table at 32 directions a hemisphere.
  for (double tau : {0.5, 3.0}) {
    const ShadowedFog fog(tau, 20.0, make_box({-1e5, -1e5, kTop + 1}, {1e5, 1e5, kTop + 2}));
    const FogDiffuseField& field = *fog.sky_light.diffuse_field();
    const Vec3 point{0, 0, 0.01}, up{0, 0, 1};
    ASSERT_TRUE(fog.shadowed.shaded(point, up));
    const Vec3 sun_horizontal = normalize(Vec3{fog.sky.to_sun().x, fog.sky.to_sun().y, 0.0});
    Spectrum expected(0.0f);
    constexpr int kElevations = 200, kAzimuths = 400;
    for (int i = 0; i < kElevations; ++i) {
      const double e = 0.5 * kPi * (i + 0.5) / kElevations;
      for (int j = 0; j < kAzimuths; ++j) {
        const double a = 2 * kPi * (j + 0.5) / kAzimuths;
        const Vec3 from{std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
        // The light travels along −from; its azimuth from the sunbeam's, which travels
        // along −sun_horizontal (the field is the same at ±φ).
        const Vec3 travel = -from, beam = -sun_horizontal;
        const double travel_azimuth =
            std::atan2(travel.x * beam.y - travel.y * beam.x, travel.x * beam.x + travel.y * beam.y);
        const Spectrum single = field.radiance(point.z, -from.z, travel_azimuth) -
                                field.radiance_without_sun(point.z, -from.z, travel_azimuth);
        const double weight = std::sin(e) * std::cos(e) * (0.5 * kPi / kElevations) * (2 * kPi / kAzimuths);
        expected += single * static_cast<float>(weight);
      }
    }
    const Spectrum missing = fog.shadowed.missing_irradiance(point, up);
    for (int k = 0; k < kSpectralBins; k += 13) {
      ASSERT_GT(expected[k], 0.0f);
      EXPECT_NEAR(missing[k], expected[k], 0.01 * expected[k]) << "τ " << tau << ", bin " << k;
    }
  }
}

}  // namespace
}  // namespace skylit
