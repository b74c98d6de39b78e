// The spectral Monte Carlo reference (`path`, DESIGN.md): the same prepared scene as
// the fast method, with every bounce of light between surfaces, so that what the fast
// method approximates (one bounce of sky light, obstacles lit by the open sky, or with
// `render.obstacle_light` "own_sky" a few bounces closed by a geometric series; the fog's
// light as a layer's) can be measured against it
// (docs/validation.md).
//
// A path carries all spectral bins at once (the materials and the air are what make
// light spectral; nothing here changes a path's direction by wavelength). In fog it
// scatters where free-flight sampling in the layer's density puts it
// (media/fog_free_flight.h), in clouds where delta tracking against their exact solids
// does (clouds/cloud_tracking.h), in directions drawn from each medium's phase function
// (media/phase_sampler.h), as often as it takes: full multiple scattering. Shadow rays
// cross the clouds by ratio tracking, the fog by its closed-form transmittance. At each
// surface and each scattering event it takes next-event estimates of the sun (a directional source of the sky
// model's direct irradiance at the point's height, as the fast path), of the sky (drawn
// by sky/sky_sampler.h and weighed against the material's own sampling by the power
// heuristic, Veach 1997) and of every lamp (point sources, their intensity
// distributions), then continues in a direction drawn from the material
// (material/reflection_sampling.h), with Russian roulette from the fourth bounce. The
// camera's ray crosses the air as in the fast path (aerial perspective from its
// tables); the sun's disc is seen where a camera ray or a mirror's reflection meets it.
//
#pragma once

#include <memory>
#include <optional>

#include "skylit/core/counter_random.h"
#include "skylit/media/phase_sampler.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/render/primary_hits.h"
#include "skylit/sky/sky_sampler.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// Light of a uniform radiance from above the horizon and another from below, without
// the sun or the air, in place of the sky: for tests against independent solutions. The
// "white furnace" (the same radiance everywhere), in which a scene of non-absorbing
// surfaces must look exactly as bright as its surroundings; a slab of fog under a
// uniform sky over a black ground, as adding–doubling solves it.
struct TestEnvironment {
  Spectrum above;
  Spectrum below;
};

class PathIntegrator {
 public:
  explicit PathIntegrator(const PreparedScene& scene);
  PathIntegrator(const PreparedScene& scene, const TestEnvironment& environment);

  // One path's estimate of the radiance arriving along a camera ray.
  Radiance sample(const Ray& camera_ray, CounterRandom& random) const;

  // The longest path (bounces and scattering events) before it is cut; Russian roulette
  // ends almost all far sooner. Diffusion through a fog of optical depth τ takes ~τ²
  // events, so the cap is far above what τ = 30 needs.
  static constexpr int kMaxEvents = 100000;

 private:
  // How a point scatters light toward the viewer: a surface's reflection, or the phase
  // function of the fog or a cloud at a point in it.
  enum class ScattererKind { surface, fog, cloud };
  struct Scatterer {
    ScattererKind kind;
    const Material* material = nullptr;  // for a surface
    Vec3 normal{};                       // for a surface
  };
  // The light a surface or fog point sends toward `to_viewer` directly from the sun,
  // the sky (weighed against the point's own sampling) and the lamps.
  Radiance direct_light(const Vec3& position, const Scatterer& scatterer, const Vec3& to_viewer,
                        CounterRandom& random) const;
  CosineWeightedBrdf scattering_cos(const Scatterer& scatterer, const Vec3& to_light, const Vec3& to_viewer) const;
  double scattering_pdf(const Scatterer& scatterer, const Vec3& to_light, const Vec3& to_viewer) const;
  // The transmittance of the fog and the clouds from a point toward a direction, to
  // `distance` (the clouds' by an unbiased estimate).
  Transmittance media_transmittance(const Vec3& point, const Vec3& direction, double distance,
                                    CounterRandom& random) const;
  const PhaseSampler& phase_sampler(ScattererKind kind) const {
    return kind == ScattererKind::fog ? *fog_phase_ : *cloud_phase_;
  }

  // The radiance arriving from a direction: the sky's (as surfaces near the ground
  // receive it), or the test environment's.
  Radiance environment(const Vec3& direction) const;

  const PreparedScene& scene_;
  std::optional<TestEnvironment> test_environment_;
  SkySampler sky_sampler_;
  std::unique_ptr<PhaseSampler> fog_phase_;    // with fog only
  std::unique_ptr<PhaseSampler> cloud_phase_;  // with clouds only
};

}  // namespace skylit
