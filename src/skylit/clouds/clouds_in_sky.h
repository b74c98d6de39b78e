// The scene's clouds under its sky: how they are lit (Eq. 15: the sun at the clouds'
// altitude; the sky's and the ground's diffuse light there), what they do
// to a view ray (Eq. 16, as a stretch of medium), the shadows they cast, and how much
// of the sky light they let through to the ground. Built once per scene from the
// atmosphere's sky model; read by the renderer from any thread.
#pragma once

#include <optional>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/clouds/cloud_layer.h"
#include "skylit/clouds/cloud_sky_share.h"
#include "skylit/spectrum/medium_stretch.h"

namespace skylit {

class CloudsInSky {
 public:
  // The clouds given one by one and those of a generated layer, if any; `camera_ground`
  // is the ground below the camera, around which the share of sky light under the
  // clouds is tabulated (cloud_sky_share.h); `model` how their multiple scattering is
  // found (cloud_scattering.h); `share_cells` bounds the share's grid (cells on a side).
  CloudsInSky(const std::vector<CloudShape>& listed, const std::optional<CloudLayerSettings>& generated,
              const SkyModel& sky, const Vec3& camera_ground, CloudLightModel model = CloudLightModel::two_stream,
              int share_cells = CloudSkyShare::kMaxCells);

  // What the clouds do along a view ray from its origin up to `distance` (may be
  // infinite), and where the ray enters the first cloud (infinite if none).
  struct Along {
    MediumStretch stretch;
    double entry_distance;
  };
  Along along(const Vec3& origin, const Vec3& direction, double distance) const;

  // e^{−t'} toward the sun from a point (the clouds' shadows).
  double sun_transmittance(const Vec3& point) const { return layer_.sun_transmittance(point, to_sun_); }

  // The sky irradiance under the clouds over that under the clear sky on a surface at
  // `point` facing `normal`, per bin: how the clouds scale the sky light on surfaces.
  Transmittance sky_share(const Vec3& point, const Vec3& normal) const { return sky_share_.at(point, normal); }

  const CloudLayer& layer() const { return layer_; }
  const CloudSkyShare& sky_share_grid() const { return sky_share_; }
  // The share of the sun's and the sky's light the clouds are given: the generated
  // layer's light_share, or the one fitted to its diffuse_horizontal_lux (the fit's
  // unbounded value in fitted_light_share, for reports).
  double light_share() const { return light_share_; }
  double fitted_light_share() const { return fitted_light_share_; }

 private:
  CloudLayer layer_;
  Vec3 to_sun_;
  double fitted_light_share_ = 1, light_share_ = 1;
  CloudLighting lighting_;
  CloudSkyShare sky_share_;
};

}  // namespace skylit
