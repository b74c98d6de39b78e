// Sky light on the scene's surfaces with the sky hidden by other objects (§4 of the
// paper): the diffuse irradiance that the sky dome's band sources give a point, where
// elements hidden by obstacles (other buildings, the ground) are replaced by the light
// those obstacles send back (one bounce).
//
// The unobstructed irradiance comes from the sky model's table over orientations (the
// paper's look-up table for diffuse reflection); what obstacles change is found by
// tracing one ray per band-source element toward the sky (rather than intersecting each
// band's sample plane with the obstacles as the paper does: Embree makes the rays cheap
// and handles any mesh), and subtracting the hidden sky's share while adding the
// obstacle's.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/sky/band_sources.h"

namespace skylit {

// Radiance (W m⁻² sr⁻¹ nm⁻¹) that the obstacle hit by `ray` sends back along it.
using ObstacleRadiance = std::function<Spectrum(const Ray& ray, const Hit& hit, uint64_t& rays)>;

class SkyLight {
 public:
  // Directions for finding what obstacles hide: a spherical Fibonacci set, chosen over
  // the paper's band elements by measurement (docs/sky-light.md): point samples on the
  // bands' regular lattice line up with straight building edges and misjudge a street
  // canyon's sky by up to 0.03 of the view factor at 1024 rays; this set, by 0.01.
  static constexpr int kDefaultDirections = 1024;

  SkyLight(const SkyModel& sky, const RayTracer& tracer, ObstacleRadiance obstacle_radiance,
           std::vector<SkyElement> directions = fibonacci_sphere(kDefaultDirections));

  // Irradiance (W m⁻² nm⁻¹) on a surface at `point` with unit `normal` (facing the side
  // being lit), from the sky, the far ground, and the obstacles that hide them.
  Spectrum diffuse_irradiance(const Vec3& point, const Vec3& normal, uint64_t& rays) const;

  // The sky view factor at a point: the share of a cosine-weighted hemisphere that sees
  // the sky (z > 0) unobstructed. 1 for a horizontal surface in the open.
  double sky_view_factor(const Vec3& point, const Vec3& normal, uint64_t& rays) const;

 private:
  Vec3 offset_point(const Vec3& point, const Vec3& normal) const;

  const SkyModel& sky_;
  const RayTracer& tracer_;
  ObstacleRadiance obstacle_radiance_;
  std::vector<SkyElement> elements_;
  std::vector<Spectrum> element_radiance_;  // the sky (or far ground) at each element
};

}  // namespace skylit
