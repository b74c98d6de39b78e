// The spectral Monte Carlo reference (`path`, DESIGN.md): the same prepared scene as
// the fast method, with every bounce of light between surfaces, so that what the fast
// method approximates (one bounce of sky light, obstacles lit by the unobstructed sky,
// no light reflected by glossy facades onto others) can be measured against it
// (docs/validation.md).
//
// A path carries all spectral bins at once (the materials and the air are what make
// light spectral; nothing here changes a path's direction by wavelength). At each
// surface it takes next-event estimates of the sun (a directional source of the sky
// model's direct irradiance at the point's height, as the fast path), of the sky (drawn
// by sky/sky_sampler.h and weighed against the material's own sampling by the power
// heuristic, Veach 1997) and of every lamp (point sources, their intensity
// distributions), then continues in a direction drawn from the material
// (material/reflection_sampling.h), with Russian roulette from the fourth bounce. The
// camera's ray crosses the air as in the fast path (aerial perspective from its
// tables); the sun's disc is seen where a camera ray or a mirror's reflection meets it.
//
// Not yet: fog and clouds as participating media (scenes with them are refused).
#pragma once

#include <memory>
#include <optional>

#include "skylit/core/counter_random.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/render/primary_hits.h"
#include "skylit/sky/sky_sampler.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// A light of uniform radiance from every direction, without the sun or the air: the
// "white furnace" in which a closed or open scene of non-absorbing surfaces must look
// exactly as bright as its surroundings (a test of energy bookkeeping).
struct UniformEnvironment {
  Spectrum radiance;
};

class PathIntegrator {
 public:
  explicit PathIntegrator(const PreparedScene& scene);
  PathIntegrator(const PreparedScene& scene, const UniformEnvironment& furnace);

  // One path's estimate of the radiance arriving along a camera ray.
  Radiance sample(const Ray& camera_ray, CounterRandom& random) const;

  // The longest path (bounces) before it is cut; Russian roulette ends most far sooner.
  static constexpr int kMaxBounces = 64;

 private:
  // The light a surface point sends toward `to_viewer` directly from the sun, the sky
  // (weighed against the material's sampling) and the lamps.
  Spectrum direct_light(const SurfacePoint& point, const Vec3& to_viewer, CounterRandom& random) const;
  SurfacePoint surface_point(const Ray& ray, const Hit& hit) const;

  // The radiance arriving from a direction at a surface: the sky's, or the furnace's.
  Spectrum environment(const Vec3& direction) const;

  const PreparedScene& scene_;
  std::optional<UniformEnvironment> furnace_;
  SkySampler sky_sampler_;
};

}  // namespace skylit
