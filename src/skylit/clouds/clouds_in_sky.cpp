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

CloudLayer prepared_layer(std::vector<Cloud> clouds, const Vec3& to_sun) {
  CloudLayer layer(std::move(clouds));
  layer.prepare_sun(to_sun);
  return layer;
}

// Eq. 15: the sun at the clouds' altitude. The sky's light from above and the ground's
// from below are the irradiances the scene's surfaces get (as the path-traced reference
// lights the clouds), so that clouds stay lit by the sky after sunset.
CloudLighting cloud_lighting(const SkyModel& sky, double altitude, CloudLightModel model) {
  CloudLighting lighting;
  lighting.to_sun = sky.to_sun();
  lighting.sun = sky.direct_sun(altitude).spectrum();
  lighting.model = model;
  const Irradiance from_above = sky.sky_irradiance({0, 0, 1});
  lighting.sky_from_above = from_above.spectrum();
  lighting.sky_from_below = sky.sky_irradiance({0, 0, -1}).spectrum();
  // The paper's model: a Lambertian of albedo 0.25 under the sun and the sky.
  if (model == CloudLightModel::paper)
    lighting.ambient = default_cloud_ambient(lighting.sun, lighting.to_sun) +
                       (from_above * static_cast<float>(kDefaultCloudAmbientFraction / kPi)).spectrum();
  return lighting;
}

}  // namespace

CloudsInSky::CloudsInSky(const std::vector<CloudShape>& listed, const std::optional<CloudLayerSettings>& generated,
                         const SkyModel& sky, const Vec3& camera_ground, CloudLightModel model)
    : layer_(prepared_layer(all_clouds(listed, generated), sky.to_sun())),
      to_sun_(sky.to_sun()),
      lighting_(cloud_lighting(sky, mean_altitude(layer_.clouds()), model)),
      sky_share_(layer_, lighting_, sky, camera_ground) {}

CloudsInSky::Along CloudsInSky::along(const Vec3& origin, const Vec3& direction, double distance) const {
  const CloudScattering c = layer_.scatter(origin, direction, 0.0, std::min(distance, 1e7), lighting_);
  return {{Transmittance(static_cast<float>(c.transmittance)), Radiance(c.in_scattered)}, c.distance};
}

}  // namespace skylit
