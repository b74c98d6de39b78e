// Eq. 16 through one cloud (cloud_scattering.h): the phase function and its mean cosine,
// the default ambient, and the integral along the march.
#include "skylit/clouds/cloud_scattering.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skylit/atmosphere/phase_functions.h"
#include "skylit/clouds/cloud_march.h"
#include "skylit/media/fog_phase.h"

namespace skylit {

double cloud_phase(double cos_theta) {
  static const DropletPhaseParameters params = DropletPhaseParameters::for_diameter(kCloudDropletDiameterUm);
  const double c = std::isfinite(cos_theta) ? std::clamp(cos_theta, -1.0, 1.0) : 0.0;
  return droplet_phase(c, params);
}

double cloud_mean_cosine() {
  // 2π ∫ μ F(μ) dμ with μ = 1 − x², which resolves the forward spike (as the test of the
  // normalisation does).
  static const double g = [] {
    const int n = 200000;
    const double dx = std::sqrt(2.0) / n;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * dx;
      const double mu = 1 - x * x;
      sum += mu * cloud_phase(mu) * 2 * x * dx;
    }
    return 2 * kPi * sum;
  }();
  return g;
}

Spectrum default_cloud_ambient(const Spectrum& sun_at_cloud, const Vec3& to_sun) {
  const double len = length(to_sun);
  const double sin_h = len > 0 && std::isfinite(len) ? std::max(0.0, to_sun.z / len) : 0.0;
  return sun_at_cloud * static_cast<float>(kDefaultCloudAmbientFraction * sin_h / kPi);
}

CloudScattering scatter_through_cloud(const CloudGeometry& cloud, const SunDepthGrid& sun_depths, const Vec3& o,
                                      const Vec3& d, double t_min, double t_max, const CloudLighting& light) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  CloudScattering out;
  double t0, t1;
  if (!cloud.clip(o, d, t_min, t_max, t0, t1)) return out;
  const CloudShape& shape = cloud.shape();
  const double sigma = shape.extinction;
  const double sun_len = length(light.to_sun);
  const bool has_sun = sun_len > 0 && std::isfinite(sun_len) && !light.sun.is_black() && shape.albedo > 0;
  const Vec3 to_sun = has_sun ? light.to_sun / sun_len : Vec3{0, 0, 1};
  const Spectrum sun_source =
      has_sun ? light.sun * static_cast<float>(shape.albedo * cloud_phase(dot(d, to_sun) / std::max(length(d), 1e-300)))
              : Spectrum(0.0f);
  // With no usable sun direction t' is still taken straight up (as before).
  const bool use_grid = sun_depths.prepared_for(to_sun);
  const double similarity = 1.0 - cloud_mean_cosine();  // (1 − g): van de Hulst's similarity
  double view_depth = 0;                                // t(s): from the viewer's side of the cloud to s
  double view_transmittance = 1;                        // e^{−t(s)}, kept as a product of the steps' e^{−τ}
  // Both sources are the same spectrum at every step: sum their scalar weights (in
  // double) and scale the spectra once.
  double sun_weight = 0, ambient_weight = 0;
  march_cloud_inside(cloud, o, d, t0, t1, [&](double s0, double s1) {
    const double tau = sigma * (s1 - s0);
    const double absorbed = -std::expm1(-tau);
    const double weight = view_transmittance * absorbed;  // ∫ σ e^{−t(s)} ds over the stretch
    view_transmittance -= weight;
    const Vec3 mid = o + d * (0.5 * (s0 + s1));
    const double t_sun =
        use_grid ? sun_depths.depth_at(cloud, mid) : cloud_optical_depth(cloud, mid, to_sun, 0.0, kInf);
    // Single-scattered sun through e^{−t'} (Eq. 16); the multiple-scattering term I_a
    // through the similarity-scaled e^{−(1−g) t'} (docs/clouds.md).
    if (has_sun) sun_weight += weight * std::exp(-t_sun);
    ambient_weight += weight * std::exp(-similarity * t_sun);
    view_depth += tau;
  });
  if (has_sun) out.in_scattered += sun_source * static_cast<float>(sun_weight);
  out.in_scattered += light.ambient * static_cast<float>(ambient_weight);
  out.transmittance = std::exp(-view_depth);
  return out;
}

}  // namespace skylit
