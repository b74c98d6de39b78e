// The atmosphere of a scene: what the sun and sky look like from any point in it.
//
// `Atmosphere` holds what does not depend on the sun's position (optical properties,
// transmittance and multiple-scattering tables, the ground's sky irradiance: shared by
// every Atmosphere of the same air, atmosphere_tables.h);
// `SkyModel` adds what does, for one sun and one observer (the sky-view table, aerial
// perspective, sky irradiance on surfaces). Both are built once per scene and then only
// read, by any number of threads. The model and its constants: docs/atmosphere.md.
#pragma once

#include <memory>
#include <vector>

#include "skylit/atmosphere/aerial_perspective_table.h"
#include "skylit/atmosphere/atmosphere_settings.h"
#include "skylit/atmosphere/atmosphere_tables.h"
#include "skylit/atmosphere/sky_irradiance_table.h"
#include "skylit/atmosphere/sky_view_table.h"

namespace skylit {

class Atmosphere {
 public:
  explicit Atmosphere(const AtmosphereSettings& settings, const SpectralBands& bands = SpectralBands::render_bins());
  ~Atmosphere();

  const AtmosphereSettings& settings() const { return settings_; }
  const SpectralBands& bands() const { return bands_; }
  const AtmosphereMedium& medium() const { return tables_->medium; }
  const TransmittanceTable& transmittance() const { return tables_->transmittance; }
  const ScatteringIntegrator& integrator() const { return *tables_->integrator; }
  // The scene's ground (z = 0) as a sphere about the Earth's centre.
  double ground_radius() const { return tables_->transmittance.ground_radius(); }
  // W m⁻² nm⁻¹ at the top of the atmosphere, for the date's Earth–Sun distance.
  const Irradiance& extraterrestrial_irradiance() const { return extraterrestrial_; }
  // Direct sunlight on a plane normal to the sun at `height_m` above the ground, for the
  // sun's true elevation; 0 when the sun's centre is hidden there. From the
  // transmittance table, and exactly (its ray traced through the air, bent when the air
  // refracts, with the beam's spreading: seen_sun.h).
  Irradiance direct_sun(double height_m, double sun_elevation_rad) const;
  Irradiance direct_sun_exact(double height_m, double sun_elevation_rad) const;

 private:
  AtmosphereSettings settings_;
  SpectralBands bands_;
  std::shared_ptr<const AtmosphereTables> tables_;  // shared with every Atmosphere of the same air
  Irradiance extraterrestrial_;
};

// Direct normal irradiance at the ground (render bins) for the sun seen at this
// elevation, exactly as the scene's beam but without building the tables: for fitting
// the aerosol to a measured beam.
Irradiance direct_sun_at_ground(const AtmosphereSettings& settings, double seen_elevation_rad);

class SkyModel {
 public:
  // `true_to_sun`: the sun's true direction, outside the air, as the tables are indexed.
  // A scene gives the sun as it is seen: SunRefraction(atmosphere).true_direction
  // (seen_sun.h) turns that into this.
  SkyModel(const Atmosphere& atmosphere, const Vec3& true_to_sun, double observer_height_m);

  const Atmosphere& atmosphere() const { return atmosphere_; }
  // The direction the sun's light comes from in the scene: the sun as seen from the
  // ground, lifted by the air's refraction (the same as the true one without it).
  const Vec3& to_sun() const { return to_sun_seen_; }
  const Vec3& true_to_sun() const { return to_sun_; }

  // Radiance of the sky (and of the ground far below the horizon) seen by the
  // observer, without the sun's disc.
  Radiance sky_radiance(const Vec3& direction) const;
  // The same for a point near the ground (where the scene's surfaces are), whatever the
  // observer's height: the light that reaches surfaces from the sky and the far ground.
  Radiance sky_radiance_near_ground(const Vec3& direction) const;
  // The sun's disc as the observer sees it (limb-darkened, attenuated along its bent
  // path; where to_sun() points, not flattened); 0 off the disc.
  // When the atmosphere's light is the moon (settings().moon), the moon's disc with its
  // phase, and `to_sun` is the direction toward the moon.
  Radiance sun_radiance(const Vec3& direction) const;
  // What the air adds and lets through between the observer and a surface.
  MediumStretch aerial_perspective(const Vec3& direction, double distance_m) const;
  // The same for several distances along one direction.
  AerialPerspectiveTable::Along aerial_perspective_along(const Vec3& direction) const;
  // The part of aerial_perspective's light that the air between distances t0 and t1
  // along the direction scatters from the sun's beam once (absolute, dimmed by the air
  // in front of it): what that stretch stops adding when a building's shadow covers
  // it (render/shadowed_air.h).
  Radiance sunlit_air(const Vec3& direction, double t0_m, double t1_m) const;
  // Unobstructed sky and ground irradiance on a plane near the ground with this normal.
  Irradiance sky_irradiance(const Vec3& normal) const { return Irradiance(ground_sky_irradiance_->at(normal)); }
  // The sun's direct normal irradiance at a height above the ground, along its bent path
  // and with its spreading (seen_sun.h): computed exactly for the sun's direction at
  // heights up to kDirectSunProfileTopM, not interpolated from the transmittance table.
  Irradiance direct_sun(double height_m) const;
  // Diffuse irradiance on a horizontal plane at the observer.
  Irradiance diffuse_horizontal_at_observer() const;
  double sun_angular_radius_rad() const { return sun_angular_radius_; }

 private:
  void add_night_sky(const Atmosphere& atmosphere);

  const Atmosphere& atmosphere_;
  Vec3 to_sun_;           // true
  Vec3 to_sun_seen_;      // seen from the ground
  double sun_elevation_;  // true
  double observer_radius_;
  double sun_angular_radius_;
  static constexpr int kDirectSunProfileSize = 65;
  static constexpr double kDirectSunProfileTopM = 2000.0;
  std::vector<Irradiance> direct_sun_profile_;  // at heights top·(k/(size−1))²
  Irradiance sun_through_air_;                  // extraterrestrial × transmittance from the observer
  Spectrum sun_outside_{0.0f};                  // extraterrestrial; 0 under an overcast CIE sky
  std::unique_ptr<SkyViewTable> observer_view_;
  std::unique_ptr<SkyViewTable> ground_view_;  // the same table when the observer is near the ground
  std::unique_ptr<AerialPerspectiveTable> aerial_;
  std::unique_ptr<SkyIrradianceTable> ground_sky_irradiance_;
};

}  // namespace skylit
