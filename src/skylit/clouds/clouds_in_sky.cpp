#include "skylit/clouds/clouds_in_sky.h"

#include <algorithm>
#include <cmath>

namespace skylit {

namespace {

// The clouds given one by one, then the generated layer's.
std::vector<Cloud> all_clouds(const std::vector<CloudShape>& listed,
                              const std::optional<CloudLayerSettings>& generated) {
  std::vector<Cloud> clouds(listed.begin(), listed.end());
  if (generated) {
    const CloudLayer layer = CloudLayer::generate(*generated);
    clouds.insert(clouds.end(), layer.clouds().begin(), layer.clouds().end());
  }
  return clouds;
}

double mean_altitude(const std::vector<Cloud>& clouds) {
  double altitude = 0;
  for (const Cloud& c : clouds) altitude += c.shape().altitude;
  return altitude / static_cast<double>(std::max<size_t>(1, clouds.size()));
}

}  // namespace

CloudsInSky::CloudsInSky(const std::vector<CloudShape>& listed, const std::optional<CloudLayerSettings>& generated,
                         const SkyModel& sky, const Vec3& ground_point, CloudLightModel model)
    : layer_(all_clouds(listed, generated)), to_sun_(sky.to_sun()) {
  const double altitude = mean_altitude(layer_.clouds());
  layer_.prepare_sun(to_sun_);
  // Eq. 15: the sun at the clouds' altitude. The sky's light from above and the ground's
  // from below are the irradiances the scene's surfaces get (as the path-traced reference
  // lights the clouds), so that clouds stay lit by the sky after sunset.
  lighting_.to_sun = to_sun_;
  lighting_.sun = sky.direct_sun(altitude).spectrum();
  lighting_.model = model;
  const Irradiance from_above = sky.sky_irradiance({0, 0, 1});
  lighting_.sky_from_above = from_above.spectrum();
  lighting_.sky_from_below = sky.sky_irradiance({0, 0, -1}).spectrum();
  // The paper's model: a Lambertian of albedo 0.25 under the sun and the sky.
  if (model == CloudLightModel::paper)
    lighting_.ambient = default_cloud_ambient(lighting_.sun, to_sun_) +
                        (from_above * static_cast<float>(kDefaultCloudAmbientFraction / kPi)).spectrum();
  sky_share_ = measure_sky_share(sky, ground_point);
}

CloudsInSky::Along CloudsInSky::along(const Vec3& origin, const Vec3& direction, double distance) const {
  const CloudScattering c = layer_.scatter(origin, direction, 0.0, std::min(distance, 1e7), lighting_);
  return {{Transmittance(static_cast<float>(c.transmittance)), Radiance(c.in_scattered)}, c.distance};
}

Transmittance CloudsInSky::measure_sky_share(const SkyModel& sky, const Vec3& ground_point) const {
  // The sky over a horizontal surface, with and without the clouds in front of it, by a
  // cosine-weighted midpoint rule (16 × 32 directions).
  Radiance clear, cloudy;
  for (int i = 0; i < 16; ++i) {
    const double mu = std::sqrt((i + 0.5) / 16), sine = std::sqrt(1 - mu * mu);
    for (int j = 0; j < 32; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / 32;
      const Vec3 dir{sine * std::cos(phi), sine * std::sin(phi), mu};
      const Radiance radiance = sky.sky_radiance_near_ground(dir);
      const CloudScattering c = layer_.scatter(ground_point, dir, 0.0, 1e7, lighting_);
      clear += radiance;
      cloudy += radiance * static_cast<float>(c.transmittance) + Radiance(c.in_scattered);
    }
  }
  Spectrum share;
  for (int k = 0; k < kSpectralBins; ++k) share[k] = clear[k] > 0 ? std::min(2.0f, cloudy[k] / clear[k]) : 1.0f;
  return Transmittance(share);
}

}  // namespace skylit
