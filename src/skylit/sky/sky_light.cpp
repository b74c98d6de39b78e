#include "skylit/sky/sky_light.h"

#include <algorithm>
#include <cmath>

namespace skylit {

SkyLight::SkyLight(const SkyModel& sky, const RayTracer& tracer, ObstacleRadiance obstacle_radiance,
                   std::vector<SkyElement> elements)
    : sky_(sky),
      tracer_(tracer),
      obstacle_radiance_(std::move(obstacle_radiance)),
      elements_(std::move(elements)) {
  for (const SkyElement& e : elements_) element_radiance_.push_back(sky_.sky_radiance_near_ground(e.direction));
}

Vec3 SkyLight::offset_point(const Vec3& point, const Vec3& normal) const {
  // As for shadow rays: well above Embree's single-precision error at this distance.
  const double offset = 1e-4 + 2e-6 * std::max({std::abs(point.x), std::abs(point.y), std::abs(point.z)});
  return point + offset * normal;
}

Spectrum SkyLight::diffuse_irradiance(const Vec3& point, const Vec3& normal, uint64_t& rays) const {
  Spectrum irradiance = sky_.sky_irradiance(normal);
  const Vec3 origin = offset_point(point, normal);
  const std::vector<SkyElement>& elements = elements_;
  for (size_t i = 0; i < elements.size(); ++i) {
    const SkyElement& e = elements[i];
    const double cosine = dot(normal, e.direction);
    if (cosine <= 0) continue;
    const Ray ray{origin, e.direction};
    ++rays;
    const std::optional<Hit> hit = tracer_.intersect(ray);
    if (!hit) continue;
    // Hidden: the element's sky leaves, the obstacle's light comes in its place.
    const float weight = static_cast<float>(cosine * e.solid_angle);
    const Spectrum obstacle = obstacle_radiance_(ray, *hit, rays);
    for (int k = 0; k < kSpectralBins; ++k)
      irradiance[k] = std::max(0.0f, irradiance[k] + weight * (obstacle[k] - element_radiance_[i][k]));
  }
  return irradiance;
}

double SkyLight::sky_view_factor(const Vec3& point, const Vec3& normal, uint64_t& rays) const {
  const Vec3 origin = offset_point(point, normal);
  double visible = 0;
  for (const SkyElement& e : elements_) {
    const double cosine = dot(normal, e.direction);
    if (cosine <= 0 || e.direction.z <= 0) continue;
    ++rays;
    if (!tracer_.occluded(Ray{origin, e.direction})) visible += cosine * e.solid_angle;
  }
  return visible / kPi;
}

}  // namespace skylit
