// The `moon` and `night_sky` parts of a scene file (docs/night-sky.md): the moon from the
// ephemeris as the sky's light when the sun is down, and the night sky's own light.
#include <string>

#include "skylit/io/scene/scene_parts.h"
#include "skylit/lights/lamp_spectrum.h"
#include "skylit/sun/moon_position.h"
#include "skylit/sun/time.h"

namespace skylit {

namespace {

NightSkySettings read_night_sky(const JsonReader& j) {
  j.allow_only({"natural", "artificial_zenith_cd_m2"});
  NightSkySettings night;
  if (auto n = j.optional("natural")) night.natural = n->boolean();
  // Up to 1 cd/m²: ten times a city centre's glow (about 0.1 cd/m², Falchi et al. 2016's
  // brightest class is above 0.02 cd/m² total at the zenith).
  if (auto a = j.optional("artificial_zenith_cd_m2")) night.artificial_zenith_cd_m2 = a->number_in(0, 1);
  return night;
}

// Whether the scene's `moon` asks for the moon: true, false or "auto" (when the sun is
// below the horizon).
bool moon_wanted(const JsonReader& moon, double sun_altitude_deg) {
  if (moon.is_string()) return moon.one_of({"auto"}) == "auto" && sun_altitude_deg < 0;
  if (!moon.boolean()) return false;
  if (sun_altitude_deg >= 0)
    moon.fail("the moon lights a scene only while the sun is below the horizon (the sun is at " +
              std::to_string(sun_altitude_deg) + "°): use \"auto\" or false");
  return true;
}

}  // namespace

void read_moon_and_night_sky(const JsonReader& root, Scene& scene) {
  // The scene's artificial glow has a white LED's spectrum (4000 K, the usual new street light).
  scene.atmosphere.night_sky.artificial_spectrum = lamp_spectrum_per_candela({LampType::kLed, 4000.0, {}});
  if (auto night = root.optional("night_sky")) {
    const Spectrum spectrum = scene.atmosphere.night_sky.artificial_spectrum;
    scene.atmosphere.night_sky = read_night_sky(*night);
    scene.atmosphere.night_sky.artificial_spectrum = spectrum;
  }
  const auto moon = root.optional("moon");
  if (!moon || !moon_wanted(*moon, scene.sun.altitude_deg)) return;
  if (!scene.site || scene.time.empty())
    moon->fail("the moon is placed from the site and the time: give 'site' and 'time' (or a weather file)");
  if (scene.atmosphere.cie_sky) moon->fail("a CIE standard sky is a daylight sky: give no 'sky' with the moon");
  const OffsetDateTime when = parse_offset_date_time(scene.time, moon->source() + ": time");
  const MoonPosition m = moon_position(*scene.site, julian_day_ut(when));
  MoonSettings settings;
  settings.phase_angle_deg = m.phase_angle_deg;
  settings.distance_km = m.distance_km;
  settings.angular_radius_deg = m.angular_radius_deg;
  settings.to_sun = direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg);
  scene.atmosphere.moon = settings;
  // From here on the sky model's light stands where the moon does.
  scene.sun.altitude_deg = m.altitude_deg;
  scene.sun.azimuth_deg = m.azimuth_deg;
}

}  // namespace skylit
