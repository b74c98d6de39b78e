#include "skylit/atmosphere/atmosphere.h"

#include <algorithm>
#include <cmath>

#include "skylit/atmosphere/cie_sky_view.h"
#include "skylit/atmosphere/moon_light.h"
#include "skylit/atmosphere/night_sky.h"
#include "skylit/atmosphere/seen_sun.h"
#include "skylit/atmosphere/sun_disc.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/spectral_math.h"

namespace skylit {

namespace {
// Surfaces within this height of the ground share the ground's sky; an observer higher
// up gets a sky-view table of its own.
constexpr double kGroundLayerM = 50.0;
}  // namespace

Atmosphere::Atmosphere(const AtmosphereSettings& settings, const SpectralBands& bands)
    : settings_(settings),
      bands_(bands),
      tables_(shared_atmosphere_tables(settings, bands)),
      extraterrestrial_(Irradiance(
          settings.moon ? moon_extraterrestrial_irradiance(bands, settings.earth_sun_distance_au, *settings.moon)
                        : skylit::extraterrestrial_irradiance(bands, settings.earth_sun_distance_au))) {}

Atmosphere::~Atmosphere() = default;

Irradiance Atmosphere::direct_sun(double height_m, double sun_elevation_rad) const {
  return extraterrestrial_ * Transmittance(tables_->transmittance.sun(ground_radius() + std::max(0.0, height_m),
                                                                      std::sin(sun_elevation_rad)));
}

Irradiance Atmosphere::direct_sun_exact(double height_m, double sun_elevation_rad) const {
  return extraterrestrial_ * Transmittance(SunRefraction(*this).sunlight(ground_radius() + std::max(0.0, height_m),
                                                                         std::sin(sun_elevation_rad)));
}

Irradiance direct_sun_at_ground(const AtmosphereSettings& settings, double seen_elevation_rad) {
  const SpectralBands bands = SpectralBands::render_bins();
  const double ground = settings.earth_radius_m + settings.site_elevation_m;
  const AtmosphereMedium medium(settings, bands);
  const SunRefraction refraction(medium, ground, settings.earth_radius_m + settings.top_altitude_m);
  const double mu_true = std::sin(refraction.true_elevation(seen_elevation_rad));
  return Irradiance(extraterrestrial_irradiance(bands, settings.earth_sun_distance_au)) *
         Transmittance(refraction.sunlight(ground, mu_true));
}

SkyModel::SkyModel(const Atmosphere& atmosphere, const Vec3& true_to_sun, double observer_height_m)
    : atmosphere_(atmosphere),
      to_sun_(normalize(true_to_sun)),
      sun_elevation_(std::asin(std::clamp(to_sun_.z, -1.0, 1.0))),
      observer_radius_(atmosphere.ground_radius() +
                       std::clamp(observer_height_m, 0.0, 0.9 * atmosphere.settings().top_altitude_m)),
      sun_angular_radius_(atmosphere.settings().moon
                              ? radians(atmosphere.settings().moon->angular_radius_deg)
                              : kSunAngularRadiusAt1AuRad / atmosphere.settings().earth_sun_distance_au) {
  const double ground = atmosphere.ground_radius();
  const std::optional<CieSkySettings>& cie = atmosphere.settings().cie_sky;
  // Under an overcast CIE sky the sun is hidden: no direct beam, and the air between
  // the camera and the scene only dims (it has no sunlight to scatter).
  const bool sun_shines = !cie || cie->direct_sun;
  const Spectrum sun = sun_shines ? atmosphere.extraterrestrial_irradiance().spectrum() : Spectrum(0.0f);
  sun_outside_ = sun;
  // Direct sunlight against height, with exact column densities along the sun's
  // bent path, and its spreading.
  const SunRefraction refraction(atmosphere);
  to_sun_seen_ = refraction.seen_direction(to_sun_);
  const auto through_air = [&](double height_m, bool spread) {
    if (!sun_shines) return Irradiance(0.0f);
    return Irradiance(sun * refraction.sunlight(ground + height_m, std::sin(sun_elevation_), spread));
  };
  for (int k = 0; k < kDirectSunProfileSize; ++k) {
    const double u = static_cast<double>(k) / (kDirectSunProfileSize - 1);
    direct_sun_profile_.push_back(through_air(kDirectSunProfileTopM * u * u, true));
  }
  // The disc's radiance is dimmed along the path but not spread: the flattened disc's
  // smaller solid angle takes the spreading.
  sun_through_air_ = through_air(observer_radius_ - ground, false);
  if (cie) {
    const double ground_albedo = atmosphere.settings().ground_albedo;
    // A CIE sky's luminance is measured about the sun as seen.
    const Irradiance sun_on_ground = direct_sun(0.0) * static_cast<float>(std::max(0.0, to_sun_seen_.z));
    observer_view_ =
        cie_sky_view(*cie, atmosphere.bands(), to_sun_seen_, sun_on_ground, ground_albedo, observer_radius_, ground);
    if (observer_radius_ - ground > kGroundLayerM)
      ground_view_ =
          cie_sky_view(*cie, atmosphere.bands(), to_sun_seen_, sun_on_ground, ground_albedo, ground + 1.0, ground);
  } else {
    observer_view_ =
        std::make_unique<SkyViewTable>(atmosphere.integrator(), sun, observer_radius_, ground, sun_elevation_);
    if (observer_radius_ - ground > kGroundLayerM)
      ground_view_ = std::make_unique<SkyViewTable>(atmosphere.integrator(), sun, ground + 1.0, ground, sun_elevation_);
  }
  add_night_sky(atmosphere);
  aerial_ =
      std::make_unique<AerialPerspectiveTable>(atmosphere.integrator(), sun, observer_radius_, ground, sun_elevation_);
  ground_sky_irradiance_ =
      std::make_unique<SkyIrradianceTable>(ground_view_ ? *ground_view_ : *observer_view_, to_sun_);
}

void SkyModel::add_night_sky(const Atmosphere& atmosphere) {
  const AtmosphereSettings& settings = atmosphere.settings();
  if (settings.cie_sky) return;  // a CIE sky is a daylight sky, measured whole
  const NightSky night(settings.night_sky, atmosphere.bands(), atmosphere.transmittance(), settings.earth_radius_m);
  if (night.empty()) return;
  // The ground below the horizon reflects the night sky's light (Lambertian).
  const Spectrum ground = night.horizontal_irradiance() * static_cast<float>(settings.ground_albedo / kPi);
  const auto radiance = [&](const RelativeDirection& d) {
    return d.elevation_rad > 0 ? night.radiance(std::sin(d.elevation_rad)) : ground;
  };
  observer_view_->add(radiance);
  if (ground_view_) ground_view_->add(radiance);
}

Irradiance SkyModel::direct_sun(double height_m) const {
  if (height_m >= kDirectSunProfileTopM) return atmosphere_.direct_sun(height_m, sun_elevation_);
  const double f = std::sqrt(std::max(0.0, height_m) / kDirectSunProfileTopM) * (kDirectSunProfileSize - 1);
  const int k = std::min(static_cast<int>(f), kDirectSunProfileSize - 2);
  const float a = static_cast<float>(f - k);
  return direct_sun_profile_[static_cast<size_t>(k)] * (1 - a) + direct_sun_profile_[static_cast<size_t>(k + 1)] * a;
}

Radiance SkyModel::sky_radiance(const Vec3& direction) const {
  return Radiance(observer_view_->radiance(relative_direction(direction, to_sun_)));
}

Radiance SkyModel::sky_radiance_near_ground(const Vec3& direction) const {
  return Radiance((ground_view_ ? *ground_view_ : *observer_view_).radiance(relative_direction(direction, to_sun_)));
}

Radiance SkyModel::sun_radiance(const Vec3& direction) const {
  const double angle = std::acos(std::clamp(dot(normalize(direction), to_sun_seen_), -1.0, 1.0));
  if (angle >= sun_angular_radius_) return Radiance(0.0f);
  if (const std::optional<MoonSettings>& moon = atmosphere_.settings().moon)
    return Radiance(moon_disc_radiance(sun_through_air_.spectrum(), *moon, to_sun_seen_, direction));
  return Radiance(sun_disc_radiance(sun_through_air_.spectrum(), atmosphere_.bands(), sun_angular_radius_, angle));
}

MediumStretch SkyModel::aerial_perspective(const Vec3& direction, double distance_m) const {
  return aerial_->at(relative_direction(direction, to_sun_), distance_m);
}

AerialPerspectiveTable::Along SkyModel::aerial_perspective_along(const Vec3& direction) const {
  return aerial_->along(relative_direction(direction, to_sun_));
}

Radiance SkyModel::sunlit_air(const Vec3& direction, double t0_m, double t1_m) const {
  // Stretches within a scene are short and near the ground, where the density and the
  // sun change little over a step even on a slanting view: 250 m steps agree with the
  // integrator's own crowded segments within 0.5 % up to 3 km on a view rising 17°
  // (tests/render/shadowed_air_test.cpp; 500 m steps 0.55 %).
  constexpr double kMaxStepM = 250.0;
  const Vec3 d = normalize(direction);
  return Radiance(atmosphere_.integrator().sun_single_scattering(observer_radius_, d.z, std::sin(sun_elevation_),
                                                                 dot(d, to_sun_), t0_m, t1_m, kMaxStepM) *
                  sun_outside_);
}

Irradiance SkyModel::diffuse_horizontal_at_observer() const {
  return Irradiance(SkyIrradianceTable::integrate(*observer_view_, {kPi / 2, 0.0}));
}

}  // namespace skylit
