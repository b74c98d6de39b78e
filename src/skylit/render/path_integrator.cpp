#include "skylit/render/path_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "skylit/clouds/cloud_scattering.h"
#include "skylit/clouds/cloud_tracking.h"
#include "skylit/material/reflection.h"
#include "skylit/material/reflection_sampling.h"
#include "skylit/media/fog_free_flight.h"

namespace skylit {

namespace {

double power_heuristic(double a, double b) { return a * a / (a * a + b * b); }

// Russian roulette from the fourth event: a path goes on with a chance that follows its
// throughput, and then carries the inverse of that chance (unbiased). While the
// throughput is 1 or more it goes on for sure: in a non-absorbing cloud the throughput
// stays 1 over the hundreds of events of diffusion, and any fixed chance below 1 would
// compound there into rare paths of weight in the thousands (with a cap of 0.95, a slab
// of optical depth 20 read 25 % low after 256,000 paths). `exempt`: a path travelling
// within the sun's spike cone goes on whatever its weight (path_integrator.h).
bool survives_roulette(int event, bool exempt, Spectrum& throughput, CounterRandom& random) {
  if (event < 3 || exempt) return true;
  const double survive = std::min(1.0, throughput.mean_value());
  if (random.uniform() >= survive) return false;
  throughput *= static_cast<float>(1.0 / survive);
  return true;
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Shadow rays toward the sky end here: above any cloud (as in clouds/clouds_in_sky.cpp).
constexpr double kSkyDistanceM = 1e7;

}  // namespace

PathIntegrator::PathIntegrator(const PreparedScene& scene) : scene_(scene), sky_sampler_(scene.sky()) {
  if (const FogMedium* fog = scene.fog()) {
    const FogLayer& layer = fog->layer();
    fog_phase_ = std::make_unique<PhaseSampler>([&layer](double c) { return layer.phase(c); });
  }
  if (scene.clouds()) cloud_phase_ = std::make_unique<PhaseSampler>([](double c) { return cloud_phase(c); });
  spike_phase_ = cloud_phase_ ? cloud_phase_.get() : fog_phase_.get();
  if (spike_phase_) spike_cone_ = spike_phase_->cone(radians(kSpikeConeDeg));
}

PathIntegrator::PathIntegrator(const PreparedScene& scene, const TestEnvironment& environment) : PathIntegrator(scene) {
  test_environment_ = environment;
  sky_sampler_ = SkySampler([this](const Vec3& direction) { return this->environment(direction).spectrum(); });
}

Radiance PathIntegrator::environment(const Vec3& direction) const {
  if (test_environment_) return Radiance(direction.z > 0 ? test_environment_->above : test_environment_->below);
  return scene_.sky().sky_radiance_near_ground(direction);
}

Radiance PathIntegrator::sky_through_media(const Vec3& point, const Vec3& direction, bool from_surface,
                                           CounterRandom& random) const {
  const Radiance sky = environment(direction);
  const Transmittance fog =
      scene_.fog() ? Transmittance(fog_transmittance(scene_.fog()->layer(), Ray{point, direction}, kInfinity))
                   : Transmittance(1.0f);
  const CloudsInSky* clouds = scene_.clouds();
  if (!clouds) return sky * fog;
  // From a surface through a cloud: t·S + (1 − t)·A, the cloud in place of the sky
  // beyond it, seen through the air before it (medium_stretch.h; its own light comes
  // from the paths that scatter in it); t estimated, the sum linear in it. The fog's
  // transmittance dims both.
  std::optional<CloudLayer::Crossing> entry;
  if (from_surface && !test_environment_) {
    entry = clouds->layer().first_hit(point, direction, 0.0, kSkyDistanceM);
    if (!entry) return sky * fog;
  }
  const auto t =
      static_cast<float>(estimate_cloud_transmittance(clouds->layer(), point, direction, kSkyDistanceM, random));
  if (!entry) return sky * (fog * t);
  const MediumStretch air = scene_.sky().aerial_perspective(direction, std::max(entry->t_enter, 0.0));
  return seen_past(sky, air, {Transmittance(t), Radiance(0.0f)}) * fog;
}

CosineWeightedBrdf PathIntegrator::scattering_cos(const Scatterer& scatterer, const Vec3& to_light,
                                                  const Vec3& to_viewer) const {
  if (scatterer.kind == ScattererKind::surface)
    return reflection_cos(*scatterer.material, scatterer.normal, to_light, to_viewer);
  // In a medium: the phase function per unit of scattering (the albedo is in the
  // collision's weight).
  const double cos_theta = dot(-to_viewer, to_light);
  const double phase =
      scatterer.kind == ScattererKind::fog ? scene_.fog()->layer().phase(cos_theta) : cloud_phase(cos_theta);
  return {Spectrum(static_cast<float>(phase))};
}

double PathIntegrator::scattering_pdf(const Scatterer& scatterer, const Vec3& to_light, const Vec3& to_viewer) const {
  if (scatterer.kind == ScattererKind::surface)
    return reflection_pdf(*scatterer.material, scatterer.normal, to_light, to_viewer);
  return phase_sampler(scatterer.kind).pdf(dot(-to_viewer, to_light));
}

bool PathIntegrator::sun_spike_strategy() const { return spike_phase_ && !test_environment_ && scene_.to_sun().z > 0; }

bool PathIntegrator::in_spike_cone(const Vec3& direction) const {
  return dot(scene_.to_sun(), direction) > spike_cone_.min_cos;
}

double PathIntegrator::spike_cone_pdf(const Vec3& direction) const {
  return spike_phase_->pdf_within(spike_cone_, dot(scene_.to_sun(), direction));
}

Spectrum PathIntegrator::spike_path(const Vec3& position, const Scatterer& scatterer, const Vec3& to_viewer,
                                    const Spectrum& throughput, int event, int spike_depth,
                                    CounterRandom& random) const {
  const double u1 = random.uniform(), u2 = random.uniform();
  const PhaseSampler::Sample drawn = spike_phase_->sample_within(spike_cone_, scene_.to_sun(), u1, u2);
  const Vec3& next = drawn.direction;
  const bool surface = scatterer.kind == ScattererKind::surface;
  if (surface && dot(scatterer.normal, next) <= 0) return Spectrum(0.0f);
  const CosineWeightedBrdf f = scattering_cos(scatterer, next, to_viewer);
  const double own = scattering_pdf(scatterer, next, to_viewer), cone = spike_cone_pdf(next);
  if (f.per_sr.is_black() || !(cone > 0)) return Spectrum(0.0f);
  // f over the density drawn with, times this strategy's balance-heuristic weight
  // cone / (own + cone).
  PathState sub;
  sub.ray = Ray{surface ? offset_from_surface(position, scatterer.normal) : position, next};
  sub.throughput = throughput * f.per_sr * static_cast<float>(cone / ((own + cone) * drawn.pdf));
  sub.delta = false;
  sub.scatter_pdf = own;  // the sky it meets is weighed as the own strategy's would be
  sub.event = event + 1;
  sub.from_surface = surface;
  return trace(sub, spike_depth, random, nullptr);
}

Radiance PathIntegrator::direct_light(const Vec3& position, const Scatterer& scatterer, const Vec3& to_viewer,
                                      CounterRandom& random) const {
  const SkyModel& sky = scene_.sky();
  const RayTracer& tracer = scene_.tracer();
  const bool surface = scatterer.kind == ScattererKind::surface;
  const Vec3 origin = surface ? offset_from_surface(position, scatterer.normal) : position;
  auto faces = [&](const Vec3& direction) { return !surface || dot(scatterer.normal, direction) > 0; };
  Radiance light(0.0f);
  // The sun, a direction with the direct irradiance of the sky model at this height.
  const Vec3& to_sun = scene_.to_sun();
  if (!test_environment_ && faces(to_sun)) {
    const Irradiance sun = sky.direct_sun(position.z);
    if (sun[kSpectralBins - 1] > 0.0f && !tracer.occluded(Ray{origin, to_sun})) {
      Irradiance reaching = sun;
      if (const FogMedium* fog = scene_.fog()) reaching *= fog->sun_transmittance(position);
      if (const CloudsInSky* clouds = scene_.clouds())
        reaching *=
            static_cast<float>(estimate_cloud_transmittance(clouds->layer(), position, to_sun, kSkyDistanceM, random));
      light += scattering_cos(scatterer, to_sun, to_viewer).reflect(reaching);
    }
  }
  // The sky, one direction drawn from its table.
  const double u1 = random.uniform(), u2 = random.uniform();
  const SkySampler::Sample s = sky_sampler_.sample(u1, u2);
  if (faces(s.direction) && s.pdf > 0) {
    const CosineWeightedBrdf f = scattering_cos(scatterer, s.direction, to_viewer);
    if (!f.per_sr.is_black() && !tracer.occluded(Ray{origin, s.direction})) {
      const double weight = power_heuristic(s.pdf, scattering_pdf(scatterer, s.direction, to_viewer));
      // One direction standing for the whole sphere: its radiance over its density.
      light += f.reflect(sky_through_media(origin, s.direction, surface, random), weight / s.pdf);
    }
  }
  // Every lamp, a point source (its irradiance already through the fog).
  if (const SceneLamps* lamps = scene_.lamps()) {
    for (size_t i = 0; i < lamps->size(); ++i) {
      const Vec3 to_lamp = lamps->position(i) - position;
      const double distance = length(to_lamp);
      if (!(distance > 0)) continue;
      const Vec3 direction = to_lamp / distance;
      if (!faces(direction)) continue;
      const CosineWeightedBrdf f = scattering_cos(scatterer, direction, to_viewer);
      if (f.per_sr.is_black()) continue;
      Irradiance irradiance = lamps->irradiance_from(i, position);
      if (irradiance.is_black()) continue;
      if (tracer.occluded(Ray{origin, direction, 0.0, distance * (1 - 1e-6)})) continue;
      if (const CloudsInSky* clouds = scene_.clouds())
        irradiance *=
            static_cast<float>(estimate_cloud_transmittance(clouds->layer(), position, direction, distance, random));
      light += f.reflect(irradiance);
    }
  }
  return light;
}

Radiance PathIntegrator::sample(const Ray& camera_ray, CounterRandom& random) const {
  PathState camera;
  camera.ray = camera_ray;
  MediumStretch camera_air;  // the air between the camera and where its ray first scatters
  const Spectrum radiance = trace(camera, 0, random, &camera_air);
  return camera_air.seen_through(Radiance(radiance));
}

Spectrum PathIntegrator::trace(PathState path, int spike_depth, CounterRandom& random,
                               MediumStretch* camera_air) const {
  const SkyModel& sky = scene_.sky();
  const RayTracer& tracer = scene_.tracer();
  const FogLayer* fog = scene_.fog() ? &scene_.fog()->layer() : nullptr;
  const CloudLayer* clouds = scene_.clouds() ? &scene_.clouds()->layer() : nullptr;
  const bool sun_spike = sun_spike_strategy();
  Ray& ray = path.ray;
  Spectrum& throughput = path.throughput;
  // The light gathered so far.
  Spectrum radiance(0.0f);
  // Whether an event at the end of the present ray sends a spike path: not from within
  // the cone (there the path's own direction and the spike path's would both follow the
  // same peak, and spike paths sent from spike paths that Russian roulette spares there
  // would multiply without end), and not deeper than kMaxSpikeDepth.
  auto sends_spike_path = [&] { return sun_spike && spike_depth < kMaxSpikeDepth && !in_spike_cone(ray.direction); };
  // After a surface or medium event: the own direction's weight against the spike
  // path's where one was sent, and whether the path may be cut (not within the cone).
  auto went_on = [&](double own_pdf) {
    if (own_pdf > 0) {
      const double cone = spike_cone_pdf(ray.direction);
      throughput *= static_cast<float>(own_pdf / (own_pdf + cone));
    }
    return survives_roulette(path.event, sun_spike && in_spike_cone(ray.direction), throughput, random);
  };
  for (; path.event < kMaxEvents; ++path.event) {
    const int event = path.event;
    const std::optional<Hit> hit = tracer.intersect(ray);
    const double t_hit = hit ? hit->t : kInfinity;
    // The media: a cloud's collision first (it bounds how far the fog's flight may go),
    // then the fog's; the nearer event is where the path scatters.
    CloudCollision cloud;
    if (clouds)
      cloud = sample_cloud_collision(*clouds, ray.origin, ray.direction, std::min(t_hit, kSkyDistanceM), random);
    std::optional<double> medium_event;
    if (cloud.collided) medium_event = cloud.distance;
    ScattererKind medium_kind = ScattererKind::cloud;
    if (fog) {
      const double u_bin = random.uniform(), u_depth = random.uniform();
      const FogFlight flight = sample_fog_flight(*fog, ray, medium_event ? *medium_event : t_hit, u_bin, u_depth);
      throughput *= flight.weight;
      if (flight.scattered) {
        medium_event = flight.distance;
        medium_kind = ScattererKind::fog;
      }
    }
    // The cloud's albedo only where the cloud is what scattered.
    if (medium_event && medium_kind == ScattererKind::cloud) throughput *= static_cast<float>(cloud.albedo);
    if (medium_event) {
      const Vec3 at = ray.origin + *medium_event * ray.direction;
      if (camera_air && event == 0 && !test_environment_)
        *camera_air = sky.aerial_perspective(ray.direction, *medium_event);
      // From a surface into a cloud: the air before the cloud, as the camera's ray has it
      // (its light, and the cloud's light through it). The air's light is part of the sky
      // light the surface's sky sample also gathers (sky_through_media), so it is weighed
      // as the sky met by this direction is.
      if (path.from_surface && medium_kind == ScattererKind::cloud && !test_environment_) {
        const MediumStretch air = sky.aerial_perspective(ray.direction, *medium_event);
        const double weight = path.delta ? 1.0 : power_heuristic(path.scatter_pdf, sky_sampler_.pdf(ray.direction));
        radiance += throughput * air.in_scattered.spectrum() * static_cast<float>(weight);
        throughput *= air.transmittance.spectrum();
      }
      path.from_surface = false;
      const Vec3 to_viewer = -ray.direction;
      const Scatterer scatterer{medium_kind};
      radiance += throughput * direct_light(at, scatterer, to_viewer, random).spectrum();
      const bool spike = sends_spike_path();
      if (spike) radiance += spike_path(at, scatterer, to_viewer, throughput, event, spike_depth + 1, random);
      const double u1 = random.uniform(), u2 = random.uniform();
      const PhaseSampler::Sample next = phase_sampler(medium_kind).sample(ray.direction, u1, u2);
      throughput *= scattering_cos(scatterer, next.direction, to_viewer).per_sr * static_cast<float>(1.0 / next.pdf);
      path.delta = false;
      path.scatter_pdf = next.pdf;
      ray = Ray{at, next.direction};
      if (!went_on(spike ? next.pdf : 0.0)) break;
      continue;
    }
    if (!hit) {
      if (event == 0 && test_environment_) {
        radiance += throughput * environment(ray.direction).spectrum();
        break;
      }
      if (event == 0) {
        // The camera sees the sky as the observer's table gives it, air included.
        radiance += throughput * (sky.sky_radiance(ray.direction) + sky.sun_radiance(ray.direction)).spectrum();
        break;
      }
      Radiance arriving = environment(ray.direction);
      if (!path.delta)
        arriving *= static_cast<float>(power_heuristic(path.scatter_pdf, sky_sampler_.pdf(ray.direction)));
      else if (!test_environment_)
        arriving += sky.sun_radiance(ray.direction);
      radiance += throughput * arriving.spectrum();
      break;
    }
    const SurfacePoint point = scene_.surface_point(ray, *hit);
    if (camera_air && event == 0 && !test_environment_) {
      *camera_air = sky.aerial_perspective(ray.direction, hit->t);
      if (const ShadowedAir* shadowed = scene_.shadowed_air())
        *camera_air = shadowed->in_shadows(*camera_air, ray, hit->t);
    }
    const Vec3 to_viewer = -ray.direction;
    const PointMaterial point_material = scene_.material_at(point);
    const Material& material = point_material.get();
    // Emission is seen from the camera only, as the bands integrator shows it: surfaces
    // that shine do not light others (docs/model-materials.md).
    if (event == 0 && point.emissive) radiance += throughput * emitted_radiance(point.emission_cd_m2).spectrum();
    const Scatterer surface{ScattererKind::surface, &material, point.normal};
    radiance += throughput * direct_light(point.position, surface, to_viewer, random).spectrum();
    const bool spike = sends_spike_path();
    if (spike) radiance += spike_path(point.position, surface, to_viewer, throughput, event, spike_depth + 1, random);
    const double u0 = random.uniform(), u1 = random.uniform(), u2 = random.uniform();
    const std::optional<ReflectionSample> next = sample_reflection(material, point.normal, to_viewer, u0, u1, u2);
    if (!next || next->weight.is_black() || dot(next->to_light, point.normal) <= 0) break;
    throughput *= next->weight;
    path.delta = next->mirror;
    path.scatter_pdf = next->pdf;
    ray = Ray{offset_from_surface(point.position, point.normal), next->to_light};
    path.from_surface = true;
    if (!went_on(spike && !next->mirror ? next->pdf : 0.0)) break;
  }
  return radiance;
}

}  // namespace skylit
