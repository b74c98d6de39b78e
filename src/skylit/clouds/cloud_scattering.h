// Light through one cloud (§6, Eq. 16): the droplets' phase function, the ambient
// radiance standing for multiple scattering, and the integral along a viewing ray.
// Geometry is cloud_shape.h, the march cloud_march.h, t' toward the sun sun_depth_grid.h.
//
// Optics. Droplets (diameters ~ 5–50 µm) are much larger than visible wavelengths:
// extinction and phase function are taken as wavelength-independent (grey), as the
// paper says (§6). The extinction coefficient σ is uniform inside the cloud
// (kDefaultCloudExtinction, cloud_shape.h). The phase function is the droplet fit of
// Jendersie & d'Eon (2023) (media/fog_phase.h) at a droplet diameter of 20 µm: strongly
// forward-peaked (mean cosine ~0.87), with a diffraction spike within a few degrees of
// the sun. Single-scattering albedo 1.
//
// Light (Eq. 16). Along a viewing ray, the radiance leaving the cloud toward the viewer:
//
//   I_c = I_behind e^{−t_total} + ∫ σ (ω F(θ) E_sun e^{−t'(s)} + I_a e^{−(1−g) t'(s)}) e^{−t(s)} ds,
//
// with E_sun the sun's irradiance at the cloud (Eq. 15, supplied by the caller), t'(s)
// the optical depth from the point toward the sun through this cloud's 3-D shape, t(s)
// the optical depth from the point back toward the viewer, and I_a a uniform ambient
// radiance standing for multiple scattering (iii). Unlike the paper's printed Eq. 16,
// I_a is attenuated by the similarity-scaled depth e^{−(1−g) t'} (g = cloud_mean_cosine(),
// 0.879; van de Hulst's similarity relation: in a forward-scattering medium multiply
// scattered light diffuses with transport coefficient σ(1−g)), not by e^{−t'}: it still
// fades into the cloud away from the sun's side (so the sunlit side stays brighter with
// the sun behind the viewer), but thick centres no longer go black. The single-scattered
// sun keeps e^{−t'} (docs/clouds.md).
#pragma once

#include <limits>

#include "skylit/clouds/cloud_shape.h"
#include "skylit/clouds/sun_depth_grid.h"
#include "skylit/core/vec3.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

inline constexpr double kCloudDropletDiameterUm = 20.0;       // for the phase function
inline constexpr double kDefaultCloudAmbientFraction = 0.25;  // see default_cloud_ambient

// The cloud phase function F(θ) (sr⁻¹, normalised over the sphere): the droplet fit of
// media/fog_phase.h at kCloudDropletDiameterUm. cos θ = V·L for the viewing direction V
// (from the viewer into the cloud) and the direction L toward the sun.
double cloud_phase(double cos_theta);
// g = ∫ cos θ F(θ) dΩ of cloud_phase (computed once, numerically): 0.879.
double cloud_mean_cosine();

// Lighting of a cloud, from the caller's atmosphere model.
struct CloudLighting {
  Vec3 to_sun{0, 0, 1};  // unit vector toward the sun
  Spectrum sun;          // E_sun at the cloud's altitude (Eq. 15), W m⁻² nm⁻¹, normal to the beam
  Spectrum ambient;      // I_a, W m⁻² sr⁻¹ nm⁻¹
};

// A default for I_a: kDefaultCloudAmbientFraction · E_sun · max(sin h, 0) / π for the
// sun's altitude h — the radiance of a Lambertian surface of albedo 0.25 under the sun,
// about what a thick cloud's base transmits diffusely (a two-stream estimate for optical
// depth ~20 and g ~0.85 gives 0.2–0.3). The renderer may add a share of the sky's mean
// radiance for when the sun is down.
Spectrum default_cloud_ambient(const Spectrum& sun_at_cloud, const Vec3& to_sun);

// What a segment of a ray through a cloud does to light: radiance leaving = behind ·
// transmittance + in_scattered (Eq. 16).
struct CloudScattering {
  Spectrum in_scattered;
  double transmittance = 1.0;
  // Where the ray enters the first cloud it meets (m along it; infinite if none): what
  // the air between the viewer and the clouds starts from.
  double distance = std::numeric_limits<double>::infinity();
};

// In-scattered radiance and transmittance of the segment of the viewing ray o + t·d
// (d unit, from the viewer), t in [t_min, t_max], through one cloud (Eq. 16 without
// I_behind). With the sun below the horizon or E_sun black, only I_a remains (still
// through e^{−(1−g)t'}). t' comes from sun_depths if it is prepared for light.to_sun,
// else is marched.
CloudScattering scatter_through_cloud(const CloudGeometry& cloud, const SunDepthGrid& sun_depths, const Vec3& o,
                                      const Vec3& d, double t_min, double t_max, const CloudLighting& light);

}  // namespace skylit
