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
// (material/reflection_sampling.h), with Russian roulette from the fourth bounce; under
// the sun with clouds or fog it also sends a spike path toward the sun (below). The
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
#include "skylit/spectrum/medium_stretch.h"
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
  // The light a surface or medium point sends toward `to_viewer` directly from the sun,
  // the sky (weighed against the point's own sampling) and the lamps.
  Radiance direct_light(const Vec3& position, const Scatterer& scatterer, const Vec3& to_viewer,
                        CounterRandom& random) const;

  // The sun through the droplets' forward spike. In a cloud, 43 % of the scattering lies
  // within 2° of forward, so the sun's next-event estimate at a cloud event, p(cos to the
  // sun), is large only for the rare paths that arrive travelling within a degree or two
  // of the sun's direction, and more so for the chains of forward scatterings that such
  // a path then makes: unbiased, but so heavy-tailed that 100,000 paths left 10–20 %
  // standard errors (docs/clouds.md); fog droplets likewise (docs/fog.md). So after
  // every surface or medium event the path's light is gathered by two strategies joined
  // by the balance heuristic (Veach 1997): the path going on in its own direction (drawn
  // from the material or phase function, density p_own), and a spike path that starts
  // in a direction drawn from the droplets' phase function (the clouds', or without
  // clouds the fog's) around the sun's within the spike cone (density p_cone) and goes
  // on as a path of its own. A path within the cone is not cut by Russian roulette (its weight
  // is small there, and its light large) and sends no spike paths.
  bool sun_spike_strategy() const;
  bool in_spike_cone(const Vec3& direction) const;
  double spike_cone_pdf(const Vec3& direction) const;
  // The half-angle of the spike cone: the droplets' phase function holds about half its
  // scattering within it.
  static constexpr double kSpikeConeDeg = 5;
  // Spike paths from spike paths (that Russian roulette spared outside the cone) up to
  // this depth; deeper ones go on as plain paths. A bound on the work, not on the light.
  static constexpr int kMaxSpikeDepth = 4;

  // A path between events: its ray, what its next light is multiplied by, how the ray
  // was drawn (from the camera or a mirror, `delta`: nothing else could have drawn it,
  // so the sky and the sun it meets count in full; or from a material's lobes or a phase
  // function with density `scatter_pdf`: the sky it meets is then weighed against the
  // sky's own sampling), and the count of events so far.
  struct PathState {
    Ray ray{};
    Spectrum throughput{1.0f};
    bool delta = true;
    double scatter_pdf = 0;
    int event = 0;
    // Whether the ray leaves a surface (the air before a cloud it meets is then the
    // ground's: cloud_air).
    bool from_surface = false;
  };
  // The light a path gathers from here on; `camera_air` receives the air before the
  // camera ray's first event. `spike_depth`: how many spike paths deep this one is.
  Spectrum trace(PathState path, int spike_depth, CounterRandom& random, MediumStretch* camera_air) const;
  // The spike path's light from a surface or medium event (with the path's throughput).
  Spectrum spike_path(const Vec3& position, const Scatterer& scatterer, const Vec3& to_viewer,
                      const Spectrum& throughput, int event, int spike_depth, CounterRandom& random) const;
  // The sky's light arriving from `direction` at `point` through the fog and the clouds
  // (the clouds' transmittance by an unbiased estimate); from a surface, with the air's
  // light before a cloud.
  Radiance sky_through_media(const Vec3& point, const Vec3& direction, bool from_surface, CounterRandom& random) const;
  CosineWeightedBrdf scattering_cos(const Scatterer& scatterer, const Vec3& to_light, const Vec3& to_viewer) const;
  double scattering_pdf(const Scatterer& scatterer, const Vec3& to_light, const Vec3& to_viewer) const;
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
  // The spike paths' phase function: the clouds' droplets, or without clouds the fog's.
  const PhaseSampler* spike_phase_ = nullptr;
  PhaseSampler::Cone spike_cone_{};  // of spike_phase_
};

}  // namespace skylit
