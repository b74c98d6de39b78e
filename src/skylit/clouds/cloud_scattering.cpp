// Eq. 16 through one cloud (cloud_scattering.h): the phase function and its mean cosine,
// the default ambient, and the integral along the march.
#include "skylit/clouds/cloud_scattering.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skylit/atmosphere/phase_functions.h"
#include "skylit/clouds/cloud_march.h"
#include "skylit/clouds/cloud_two_stream.h"
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

namespace {

// The multiple-scattering sources of the two-stream model at a point, as scalar weights of
// E_sun, the sky's irradiance from above and that from below (radiance per unit of each,
// per unit of scaled optical depth along the view).
struct TwoStreamSources {
  double sun = 0, from_above = 0, from_below = 0;
};

// cos θ_f: the droplets' phase function holds the fraction f of the delta scaling within
// θ_f of forward (f = g² = 0.773: θ_f ≈ 28°). The light the spike carries is spread over
// that cone, so the phase function that scatters it again is held flat inside it.
double spike_cone_cosine() {
  static const double cosine = [] {
    const double forward_fraction = DeltaScaling(cloud_mean_cosine()).forward_fraction;
    // ∫ F dΩ from forward outward, with μ = 1 − x² (as cloud_mean_cosine), until it reaches f.
    const int n = 200000;
    const double dx = std::sqrt(2.0) / n;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * dx, mu = 1 - x * x;
      sum += 2 * kPi * cloud_phase(mu) * 2 * x * dx;
      if (sum >= forward_fraction) return mu;
    }
    return -1.0;
  }();
  return cosine;
}

// What stays the same along one viewing ray.
struct TwoStreamRay {
  DeltaScaling scaling{cloud_mean_cosine()};
  double mu0 = 0;          // the sun's cosine with the vertical (0: no sun)
  double view_down = 0;    // downward cosine of the light travelling to the viewer
  double spike_phase = 0;  // toward the viewer, for the spike's light, per unit of scaled depth
};

TwoStreamSources two_stream_sources(const CloudGeometry& cloud, const TwoStreamRay& ray, const Vec3& p,
                                    double depth_to_sun, double depth_from_sun) {
  const double g = ray.scaling.asymmetry;
  TwoStreamSources out;
  if (ray.mu0 > 0) {
    // The slab along the sun's line through p, as a horizontal slab's vertical depths.
    const double above = ray.scaling.scaled_depth(ray.mu0 * depth_to_sun);
    const double total = above + ray.scaling.scaled_depth(ray.mu0 * depth_from_sun);
    out.sun = eddington_sun_field(total, g, ray.mu0, above).scattered(g, ray.view_down);
    // The forward spike's light, beyond what reaches p unscattered, scattered once more.
    const double spike = std::exp(-ray.scaling.scaled_depth(depth_to_sun)) - std::exp(-depth_to_sun);
    out.sun += std::max(0.0, spike) * ray.spike_phase;
  }
  // The column through p for the sky's light from above and from below.
  const CloudShape& shape = cloud.shape();
  const double thickness = cloud.thickness(p.x, p.y);
  const double column = ray.scaling.scaled_depth(shape.extinction * thickness);
  const double below_top = ray.scaling.scaled_depth(shape.extinction * (shape.altitude + 0.5 * thickness - p.z));
  out.from_above = eddington_diffuse_field(column, g, below_top, true).scattered(g, ray.view_down);
  out.from_below = eddington_diffuse_field(column, g, below_top, false).scattered(g, ray.view_down);
  return out;
}

}  // namespace

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
  const double cos_view_sun = dot(d, to_sun) / std::max(length(d), 1e-300);
  const Spectrum sun_source =
      has_sun ? light.sun * static_cast<float>(shape.albedo * cloud_phase(cos_view_sun)) : Spectrum(0.0f);
  // With no usable sun direction t' is still taken straight up (as before).
  const bool use_grid = sun_depths.prepared_for(to_sun);
  const bool two_stream = light.model == CloudLightModel::two_stream;
  // The slab solution is for ω = 1 (every cloud a scene can hold); a darker cloud's
  // multiple scattering is only scaled by ω.
  const double many_albedo = shape.albedo;
  TwoStreamRay ray;
  ray.mu0 = has_sun ? std::max(0.0, to_sun.z) : 0.0;
  ray.view_down = d.z / std::max(length(d), 1e-300);
  // The droplets' phase function itself (per unit of scaled depth: over 1 − f), held flat
  // within the cone the spike's light is spread over (spike_cone_cosine): scattering it
  // again with the peak would make thick centres glow toward the sun.
  ray.spike_phase = cloud_phase(std::min(cos_view_sun, spike_cone_cosine())) / (1 - ray.scaling.forward_fraction);
  const double scaled_sigma = ray.scaling.scaled_depth(sigma);
  double view_depth = 0;            // t(s): from the viewer's side of the cloud to s
  double view_transmittance = 1;    // e^{−t(s)}, kept as a product of the steps' e^{−τ}
  double scaled_transmittance = 1;  // e^{−(1−f)t(s)}, likewise
  // The sources are the same spectra at every step: sum their scalar weights (in
  // double) and scale the spectra once.
  double sun_weight = 0, many_weight = 0, ambient_weight = 0, above_weight = 0, below_weight = 0;
  march_cloud_inside(cloud, o, d, t0, t1, [&](double s0, double s1) {
    const double tau = sigma * (s1 - s0);
    const double weight = view_transmittance * -std::expm1(-tau);  // ∫ σ e^{−t(s)} ds over the stretch
    view_transmittance -= weight;
    view_depth += tau;
    const Vec3 mid = o + d * (0.5 * (s0 + s1));
    // t' is not needed where the sun lights no cloud (at night, in the earth's shadow)
    // and the two-stream model leaves it out of the sky's light.
    const bool needs_t_sun = has_sun || !two_stream;
    // The depth away from the sun only for the two-stream light of a sunlit cloud.
    const bool needs_t_away = two_stream && ray.mu0 > 0;
    const SunLineDepth from_grid =
        use_grid && needs_t_sun ? sun_depths.depths_at(cloud, mid, needs_t_away) : SunLineDepth{};
    const double t_sun = !needs_t_sun ? 0.0
                         : use_grid   ? from_grid.toward_sun
                                      : cloud_optical_depth(cloud, mid, to_sun, 0.0, kInf);
    if (has_sun) sun_weight += weight * std::exp(-t_sun);  // once scattered, Eq. 16
    if (!two_stream) {
      ambient_weight += weight * std::exp(-t_sun);  // I_a as printed in Eq. 16
      return;
    }
    const double scaled_absorbed = scaled_transmittance * -std::expm1(-scaled_sigma * (s1 - s0));
    scaled_transmittance -= scaled_absorbed;
    const double scaled_weight = many_albedo * scaled_absorbed;
    double t_away = 0;
    if (needs_t_away) t_away = use_grid ? from_grid.away_from_sun : cloud_optical_depth(cloud, mid, -to_sun, 0.0, kInf);
    const TwoStreamSources sources = two_stream_sources(cloud, ray, mid, t_sun, t_away);
    many_weight += scaled_weight * sources.sun;
    above_weight += scaled_weight * sources.from_above;
    below_weight += scaled_weight * sources.from_below;
  });
  // The once-scattered sun carries the phase function; the multiply scattered sun is per
  // unit of E_sun.
  if (has_sun)
    out.in_scattered += sun_source * static_cast<float>(sun_weight) + light.sun * static_cast<float>(many_weight);
  out.in_scattered += light.ambient * static_cast<float>(ambient_weight);
  if (two_stream) {
    // The light from behind the cloud that the forward spike scatters along the ray: the
    // source-function solution's boundary term, e^{−(1−f)t} of what enters the far side,
    // less the e^{−t} the caller lets through unscattered. What enters there is taken as
    // the mean radiance of the sky above or the ground below, by the ray's slope.
    const double spike_through = std::max(0.0, scaled_transmittance - view_transmittance);
    const double up = 0.5 * (1 + ray.view_down) * spike_through / kPi, down = spike_through / kPi - up;
    above_weight += many_albedo * up;
    below_weight += many_albedo * down;
  }
  out.in_scattered += light.sky_from_above * static_cast<float>(above_weight);
  out.in_scattered += light.sky_from_below * static_cast<float>(below_weight);
  out.transmittance = std::exp(-view_depth);
  return out;
}

}  // namespace skylit
