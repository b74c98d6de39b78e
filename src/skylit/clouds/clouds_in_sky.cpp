#include "skylit/clouds/clouds_in_sky.h"

#include <algorithm>
#include <cmath>

#include "skylit/spectrum/cie.h"

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
// `share` scales all of it (a generated layer's light_share).
CloudLighting cloud_lighting(const SkyModel& sky, double altitude, CloudLightModel model, double share) {
  CloudLighting lighting;
  const auto scale = static_cast<float>(share);
  lighting.to_sun = sky.to_sun();
  lighting.sun = sky.direct_sun(altitude).spectrum() * scale;
  lighting.model = model;
  const Irradiance from_above = sky.sky_irradiance({0, 0, 1}) * scale;
  lighting.sky_from_above = from_above.spectrum();
  lighting.sky_from_below = sky.sky_irradiance({0, 0, -1}).spectrum() * scale;
  // The paper's model: a Lambertian of albedo 0.25 under the sun and the sky.
  if (model == CloudLightModel::paper)
    lighting.ambient = default_cloud_ambient(lighting.sun, lighting.to_sun) +
                       (from_above * static_cast<float>(kDefaultCloudAmbientFraction / kPi)).spectrum();
  return lighting;
}

// The cells on a side of the grid of ground points the light share is fitted on.
constexpr int kFitCells = 8;

// Each cloud is lit as if it were alone (cloud_scattering.h: the two-stream slab is the
// cloud's own column and its own depth along the sun's line), but a random layer of
// cover c stacks −ln(1 − c)/c clouds over each covered point (2.6 at 9/10), which shade
// one another; and a generated cloud's optical depth is a guess. Where the clouded sky's
// diffuse light is known (a weather file's), the share of the sun's and the sky's light
// that reaches the clouds is set so that the mean over ground points around the camera
// gives it. The clouds' own light is linear in the share and nothing else the sky sends
// past them depends on it, so two measurements give it exactly: with the clouds dark
// (share 0) and lit as if alone (1).
double fit_light_share(const CloudLayer& layer, const SkyModel& sky, const Vec3& camera_ground, CloudLightModel model,
                       double target_lux) {
  const double altitude = mean_altitude(layer.clouds());
  auto mean_lux = [&](double share) {
    const CloudSkyShare grid(layer, cloud_lighting(sky, altitude, model, share), sky, camera_ground, kFitCells);
    return illuminance(grid.mean_irradiance_up());
  };
  const double dark = mean_lux(0), alone = mean_lux(1);
  return alone > dark ? (target_lux - dark) / (alone - dark) : 1.0;
}

}  // namespace

CloudsInSky::CloudsInSky(const std::vector<CloudShape>& listed, const std::optional<CloudLayerSettings>& generated,
                         const SkyModel& sky, const Vec3& camera_ground, CloudLightModel model, int share_cells)
    : layer_(prepared_layer(all_clouds(listed, generated), sky.to_sun())),
      to_sun_(sky.to_sun()),
      fitted_light_share_(generated && generated->diffuse_horizontal_lux
                              ? fit_light_share(layer_, sky, camera_ground, model, *generated->diffuse_horizontal_lux)
                              : (generated ? generated->light_share : 1.0)),
      light_share_(generated && generated->diffuse_horizontal_lux
                       ? std::clamp(fitted_light_share_, kLeastCloudLightShare, kMostCloudLightShare)
                       : fitted_light_share_),
      lighting_(cloud_lighting(sky, mean_altitude(layer_.clouds()), model, light_share_)),
      sky_share_(layer_, lighting_, sky, camera_ground, share_cells) {}

CloudsInSky::Along CloudsInSky::along(const Vec3& origin, const Vec3& direction, double distance) const {
  const CloudScattering c = layer_.scatter(origin, direction, 0.0, std::min(distance, 1e7), lighting_);
  return {{Transmittance(static_cast<float>(c.transmittance)), Radiance(c.in_scattered)}, c.distance};
}

}  // namespace skylit
