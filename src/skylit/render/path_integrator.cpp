#include "skylit/render/path_integrator.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "skylit/material/reflection.h"
#include "skylit/material/reflection_sampling.h"

namespace skylit {

namespace {

double power_heuristic(double a, double b) { return a * a / (a * a + b * b); }

double mean(const Spectrum& s) {
  double sum = 0;
  for (int k = 0; k < kSpectralBins; ++k) sum += s[k];
  return sum / kSpectralBins;
}

}  // namespace

PathIntegrator::PathIntegrator(const PreparedScene& scene) : scene_(scene), sky_sampler_(scene.sky()) {}

PathIntegrator::PathIntegrator(const PreparedScene& scene, const UniformEnvironment& furnace)
    : scene_(scene), furnace_(furnace), sky_sampler_([&furnace](const Vec3&) { return furnace.radiance; }) {}

Spectrum PathIntegrator::environment(const Vec3& direction) const {
  return furnace_ ? furnace_->radiance : scene_.sky().sky_radiance_near_ground(direction);
}

SurfacePoint PathIntegrator::surface_point(const Ray& ray, const Hit& hit) const {
  Vec3 normal = hit.geometric_normal;
  if (dot(normal, ray.direction) > 0) normal = -normal;
  return {ray.origin + hit.t * ray.direction, normal, hit.t, scene_.material_of_mesh(hit.mesh_id)};
}

Spectrum PathIntegrator::direct_light(const SurfacePoint& point, const Vec3& to_viewer, CounterRandom& random) const {
  const Material& material = scene_.material(point.material);
  const SkyModel& sky = scene_.sky();
  const RayTracer& tracer = scene_.tracer();
  const Vec3 origin = offset_from_surface(point.position, point.normal);
  Spectrum light(0.0f);
  // The sun, a direction with the direct irradiance of the sky model at this height.
  const Vec3& to_sun = scene_.to_sun();
  if (!furnace_ && dot(point.normal, to_sun) > 0) {
    const Spectrum sun = sky.direct_sun(point.position.z);
    if (sun[kSpectralBins - 1] > 0.0f && !tracer.occluded(Ray{origin, to_sun}))
      light += reflection_cos(material, point.normal, to_sun, to_viewer) * sun;
  }
  // The sky, one direction drawn from its table.
  const double u1 = random.uniform(), u2 = random.uniform();
  const SkySampler::Sample s = sky_sampler_.sample(u1, u2);
  if (dot(point.normal, s.direction) > 0 && s.pdf > 0) {
    const Spectrum f = reflection_cos(material, point.normal, s.direction, to_viewer);
    if (!f.is_black() && !tracer.occluded(Ray{origin, s.direction})) {
      const double weight = power_heuristic(s.pdf, reflection_pdf(material, point.normal, s.direction, to_viewer));
      light += f * environment(s.direction) * static_cast<float>(weight / s.pdf);
    }
  }
  // Every lamp, a point source.
  if (const SceneLamps* lamps = scene_.lamps()) {
    for (size_t i = 0; i < lamps->size(); ++i) {
      const Vec3 to_lamp = lamps->position(i) - point.position;
      const double distance = length(to_lamp);
      if (!(distance > 0)) continue;
      const Vec3 direction = to_lamp / distance;
      if (dot(point.normal, direction) <= 0) continue;
      const Spectrum f = reflection_cos(material, point.normal, direction, to_viewer);
      if (f.is_black()) continue;
      const Spectrum irradiance = lamps->irradiance_from(i, point.position);
      if (irradiance.is_black()) continue;
      if (tracer.occluded(Ray{origin, direction, 0.0, distance * (1 - 1e-6)})) continue;
      light += f * irradiance;
    }
  }
  return light;
}

Radiance PathIntegrator::sample(const Ray& camera_ray, CounterRandom& random) const {
  const SkyModel& sky = scene_.sky();
  const RayTracer& tracer = scene_.tracer();
  Spectrum radiance(0.0f), throughput(1.0f);
  Ray ray = camera_ray;
  // How the ray was drawn: from the camera or a mirror (nothing else could have drawn
  // it, so the sky and the sun it meets count in full), or from a material's lobes with
  // density `lobe_pdf` (the sky it meets is weighed against the sky's own sampling).
  bool delta = true;
  double lobe_pdf = 0;
  MediumStretch camera_air;  // the air between the camera and its first hit
  for (int bounce = 0; bounce <= kMaxBounces; ++bounce) {
    const std::optional<Hit> hit = tracer.intersect(ray);
    if (!hit) {
      if (bounce == 0 && furnace_) {
        radiance += furnace_->radiance;
        break;
      }
      if (bounce == 0) {
        // The camera sees the sky as the observer's table gives it, air included.
        radiance += sky.sky_radiance(ray.direction) + sky.sun_radiance(ray.direction);
        break;
      }
      Spectrum arriving = environment(ray.direction);
      if (!delta) arriving *= static_cast<float>(power_heuristic(lobe_pdf, sky_sampler_.pdf(ray.direction)));
      else if (!furnace_) arriving += sky.sun_radiance(ray.direction);
      radiance += throughput * arriving;
      break;
    }
    const SurfacePoint point = surface_point(ray, *hit);
    if (bounce == 0 && !furnace_) camera_air = sky.aerial_perspective(ray.direction, hit->t);
    const Vec3 to_viewer = -ray.direction;
    radiance += throughput * direct_light(point, to_viewer, random);
    const double u0 = random.uniform(), u1 = random.uniform(), u2 = random.uniform();
    const std::optional<ReflectionSample> next =
        sample_reflection(scene_.material(point.material), point.normal, to_viewer, u0, u1, u2);
    if (!next || next->weight.is_black() || dot(next->to_light, point.normal) <= 0) break;
    throughput *= next->weight;
    delta = next->mirror;
    lobe_pdf = next->pdf;
    ray = Ray{offset_from_surface(point.position, point.normal), next->to_light};
    // Russian roulette from the fourth bounce: a path goes on with a chance that follows
    // its throughput, and carries the inverse of that chance.
    if (bounce >= 3) {
      const double survive = std::min(0.95, mean(throughput));
      if (random.uniform() >= survive) break;
      throughput *= static_cast<float>(1.0 / survive);
    }
  }
  return camera_air.seen_through(Radiance(radiance));
}

}  // namespace skylit
