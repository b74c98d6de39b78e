// Light through one cloud (§6, Eq. 16): the droplets' phase function, the light
// scattered once and many times, and the integral along a viewing ray. Geometry is
// cloud_shape.h, the march cloud_march.h, t' toward the sun sun_depth_grid.h, the slab
// solution for multiple scattering cloud_two_stream.h.
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
//   I_c = I_behind e^{−t_total} + ∫ σ ω F(θ) E_sun e^{−t'(s)} e^{−t(s)} ds + (multiple scattering),
//
// with E_sun the sun's irradiance at the cloud (Eq. 15, supplied by the caller), t'(s)
// the optical depth from the point toward the sun through this cloud's 3-D shape and
// t(s) that from the point back toward the viewer: the sky behind seen through the cloud
// (i) and the sun scattered once, exactly, with the droplets' phase function (ii).
//
// Multiple scattering (iii), two models (CloudLightModel):
// - two_stream (the default): at each point the delta-Eddington field of a slab
//   (cloud_two_stream.h). For the sun's light, the slab is the cloud along the sun's line
//   through the point: the depth t' toward the sun and the depth away from it, taken as
//   the slant depths of a horizontal slab under the sun (vertical depths μ0·t', a
//   plane-parallel cloud's exactly), so a point near the sunlit surface lies near the lit
//   face whichever way that face is turned. For the sky's light (diffuse irradiance on
//   its top from the sky, on its bottom from the ground), the slab is the cloud's column
//   at the point. Each field scatters I0 + g'μI1 toward the viewer, reaching it through
//   the scaled depth e^{−(1−f)t(s)}; the light the forward spike carries past the first
//   scattering (e^{−(1−f)t'} − e^{−t'}) is scattered once more with a Henyey–Greenstein
//   phase function of mean cosine g'.
// - paper: Eq. 16 as printed: a uniform ambient radiance I_a through e^{−t(s)−t'(s)}.
//   The paper gives no value for I_a; the renderer takes a Lambertian of albedo 0.25
//   under the sun and the sky at the clouds (default_cloud_ambient). Thick clouds come
//   out 2–4 times too dark and their centres black (docs/clouds.md).
#pragma once

#include <limits>

#include "skylit/clouds/cloud_shape.h"
#include "skylit/clouds/sun_depth_grid.h"
#include "skylit/core/vec3.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

inline constexpr double kCloudDropletDiameterUm = 20.0;       // for the phase function
inline constexpr double kDefaultCloudAmbientFraction = 0.25;  // see default_cloud_ambient

// How the light scattered many times inside a cloud is found (see above).
enum class CloudLightModel { two_stream, paper };

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
  CloudLightModel model = CloudLightModel::two_stream;
  // two_stream: the diffuse irradiance on a horizontal surface at the clouds facing up
  // (the sky's) and facing down (the ground's and the air's below), W m⁻² nm⁻¹.
  Spectrum sky_from_above, sky_from_below;
  Spectrum ambient;  // paper: I_a, W m⁻² sr⁻¹ nm⁻¹
};

// The paper model's I_a: kDefaultCloudAmbientFraction · E_sun · max(sin h, 0) / π for the
// sun's altitude h — the radiance of a Lambertian surface of albedo 0.25 under the sun.
// The renderer adds the same share of the sky's irradiance for when the sun is down.
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
// I_behind). With the sun below the horizon or E_sun black, only the sky's light (or
// I_a) remains. The depths along the sun's line come from sun_depths if they are
// prepared for light.to_sun, else are marched.
CloudScattering scatter_through_cloud(const CloudGeometry& cloud, const SunDepthGrid& sun_depths, const Vec3& o,
                                      const Vec3& d, double t_min, double t_max, const CloudLighting& light);

}  // namespace skylit
