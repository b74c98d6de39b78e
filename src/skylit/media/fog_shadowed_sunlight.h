// The sunlight that the fog in the buildings' shadows does not scatter toward a surface
// (issue 13; docs/fog.md, "Surfaces in a shadow: the fog's sunlight by direction").
//
// A surface inside a multiply scattering fog is lit, from every direction it sees, by
// the open layer's field (fog_surface_light.h), and that field holds the sunlight the
// fog along the direction scatters once. Where the direction runs through a building's
// shadow, the fog there gets no sunlight and scatters none: along a view the beams of
// Eq. 21 are cut there by the shadow volumes, and this cuts the same light from what a
// surface receives. Along a direction ω from the point (the light travelling along −ω)
// the missing radiance is, over the parts in shadow before the first surface or the
// layer's end,
//   ΔL = ∫ ω₀ σ ρ(z) (1 − f) p'(cos Θ) E_sun(z) e^(−τ'(s)) ds,
// with δ-M's smooth phase function p' and spike f (the spike's light stays in the sun's
// beam, which a shaded point does not receive anyway), E_sun(z) the beam at the
// fog's altitude through the scaled depth, and τ' the scaled depth from the point
// (δ-M's transport extinction (1 − ω₀f)σ, as the field's own light travels). The
// irradiance missing on a plane is ∫ ΔL cos dω over its hemisphere, on a fixed set of
// directions with a ray each to the first surface.
//
// First order only: the fog in a shadow also lacks the light its sunlit neighbours
// would scatter toward it a second time, and sunlit fog beside a building has lost
// part of its field to the building; both are left out (docs/fog.md gives what that
// leaves on Fig. 8c–d).
#pragma once

#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/geometry/sun_shadow_volumes.h"
#include "skylit/media/fog_diffuse_field.h"
#include "skylit/media/fog_layer.h"
#include "skylit/sky/band_sources.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

class FogShadowedSunlight {
 public:
  // Directions over the sphere a renderer gives (about half of them above a plane): the
  // missing light changes smoothly with direction but at the shadows' edges, and it is
  // a correction of a tenth of the light or so (docs/fog.md measures the quadrature).
  static constexpr int kDefaultDirections = 128;

  // `to_sun` points at the sun, `sun_above_fog` is its normal irradiance at the layer's
  // top (with the sun below the horizon or its beam spent, nothing is missing anywhere);
  // `directions` cover the sphere, each with its solid angle, as the sky light's
  // (sky/band_sources.h). The references must outlive this.
  FogShadowedSunlight(const FogLayer& layer, const FogDiffuseField& field, const SunShadowVolumes& shadows,
                      const RayTracer& tracer, const Vec3& to_sun, const Spectrum& sun_above_fog,
                      std::vector<SkyElement> directions = fibonacci_sphere(kDefaultDirections));

  // Whether the sun's beam misses a surface point (on the side `normal` faces): the
  // points whose fog light this lowers. (A sunlit point's own beam outshines what the
  // fog in nearby shadows would have added.)
  bool shaded(const Vec3& point, const Vec3& normal) const;

  // ΔL (W m⁻² sr⁻¹ nm⁻¹) arriving at `point` from unit `direction`, over [0, distance]
  // (infinite: to the layer's end).
  Spectrum missing_radiance(const Vec3& point, const Vec3& direction, double distance) const;

  // ∫ ΔL cos dω (W m⁻² nm⁻¹) on the side of `normal`, each direction up to the first
  // surface it meets.
  Spectrum missing_irradiance(const Vec3& point, const Vec3& normal) const;

 private:
  const FogLayer& layer_;
  const FogDiffuseField& field_;
  const SunShadowVolumes& shadows_;
  const RayTracer& tracer_;
  Vec3 to_sun_;
  Spectrum sun_above_fog_;
  std::vector<SkyElement> directions_;
  bool sun_lights_fog_;  // the sun above the horizon, its beam not spent above the layer
  // The layer's, for the steps of missing_radiance: its most opaque bin's σ per unit
  // density, the density's vertical scale (m), its largest density.
  double sigma_max_ = 0, vertical_scale_ = 0, densest_ = 0;
};

}  // namespace skylit
