// scene_conditions (scene_conditions.h): the settings the renderer used, not the file's
// text, so that defaults and values derived by the loader (the sun from site and time,
// the aerosol depth from a visibility) are shown as they were rendered.
#include "skylit/io/scene/scene_conditions.h"

#include <cmath>
#include <cstdio>
#include <string_view>

#include "skylit/atmosphere/aerosol_types.h"

namespace skylit {

namespace {

// A number with `significant` digits, as a person writes it ("1500", "0.15", "2.5e+04").
std::string number(double value, int significant = 4) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", significant, value);
  return text;
}

std::string degrees(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f°", value);
  return text;
}

// Built by appending: "(" + a string trips GCC 12's false -Wrestrict (GCC bug 105329).
std::string point(const Vec3& p) {
  std::string text = "(";
  text += number(p.x, 6) + ", " + number(p.y, 6) + ", " + number(p.z, 6) + ") m";
  return text;
}

std::string site_text(const Scene& scene) {
  if (!scene.site) return "not given (the sun is placed directly)";
  const SiteLocation& s = *scene.site;
  return degrees(std::abs(s.latitude_deg)) + (s.latitude_deg < 0 ? " S, " : " N, ") +
         degrees(std::abs(s.longitude_deg)) + (s.longitude_deg < 0 ? " W, " : " E, ") + number(s.elevation_m) +
         " m above sea level";
}

std::string sun_text(const Scene& scene) {
  std::string text = "altitude " + degrees(scene.sun.altitude_deg) + ", azimuth " + degrees(scene.sun.azimuth_deg) +
                     " (clockwise from north)";
  if (scene.sun.altitude_deg < 0) text += "; below the horizon";
  if (scene.site) text += ", from the site and time (NREL SPA)";
  return text;
}

std::string atmosphere_text(const AtmosphereSettings& a) {
  const auto type = static_cast<std::size_t>(a.aerosol.type);
  return std::string(a.model == AtmosphereModel::paper ? "the paper's single scattering, no ozone"
                                                       : "single and multiple scattering with ozone") +
         "; aerosol " + std::string(aerosol_type_names().at(type)) + ", optical depth " + number(a.aerosol.aod_550) +
         " at 550 nm, Ångström exponent " + number(a.aerosol.angstrom_exponent) + ", scale height " +
         number(a.aerosol.scale_height_m) + " m; ozone " + number(a.ozone_column_du) + " DU; ground albedo " +
         number(a.ground_albedo);
}

// What the sky's radiance comes from: the atmosphere model's scattering, or a CIE
// standard sky scaled to an illuminance (the scene's, or an overcast weather hour's),
// which replaces it (docs/atmosphere.md).
std::string sky_text(const AtmosphereSettings& a) {
  if (!a.cie_sky) return "from the atmosphere above (scattering of the sun's light)";
  return "CIE standard general sky type " + std::to_string(a.cie_sky->type) + " (ISO 15469) scaled to " +
         number(a.cie_sky->diffuse_horizontal_lux) +
         " lx of diffuse horizontal illuminance, in place of the "
         "atmosphere's own sky; " +
         (a.cie_sky->direct_sun ? "the sun's beam from the atmosphere" : "no direct sun");
}

// The weather file's hour and what was made of it, one decision after another.
std::string weather_text(const Scene& scene) {
  if (!scene.weather) return "none (the conditions above are the scene's)";
  const WeatherSummary& w = *scene.weather;
  std::string text = w.file + ", " + w.station + ": " + w.record + "; the sun placed at " + w.sun_time;
  for (const std::string& decision : w.decisions) text += "; " + decision;
  return text;
}

std::string fog_text(const Scene& scene) {
  if (!scene.fog) return "none";
  const FogSettings& f = *scene.fog;
  const double visibility_m =
      f.ground_visibility_m.value_or(kKoschmiederConstant / (f.density_at_ground * f.unit_density_extinction_per_m));
  return "visibility " + number(visibility_m) + " m at 550 nm at the ground (Koschmieder), scale height " +
         number(f.scale_height_m) + " m, from " + number(f.bottom_altitude_m) + " m to " + number(f.top_altitude_m) +
         " m";
}

std::string clouds_text(const Scene& scene) {
  std::string text;
  if (!scene.clouds.empty()) text = std::to_string(scene.clouds.size()) + " cloud(s) placed by the scene";
  if (scene.cloud_layer) {
    if (!text.empty()) text += "; ";
    text += "a generated layer at " + number(scene.cloud_layer->altitude) + " m, coverage " +
            number(100 * scene.cloud_layer->coverage, 3) + " %";
  }
  return text.empty() ? "none" : text;
}

std::string_view projection_name(Projection p) {
  switch (p) {
    case Projection::perspective:
      return "perspective";
    case Projection::fisheye_equidistant:
      return "equidistant (angular) fisheye";
    case Projection::fisheye_equisolid:
      return "equisolid (equal-area) fisheye";
    case Projection::fisheye_hemispherical:
      return "hemispherical (orthographic) fisheye";
    case Projection::cylindrical:
      return "cylindrical panorama";
    case Projection::equirectangular:
      return "equirectangular panorama";
  }
  return "perspective";
}

std::string camera_text(const Camera& c) {
  std::string text = std::string(projection_name(c.projection)) + " at " + point(c.position) + " looking at " +
                     point(c.look_at) + "; vertical angle of view " + number(c.vertical_fov_deg) + "°";
  if (c.projection == Projection::cylindrical || c.projection == Projection::equirectangular)
    text += ", horizontal " + number(c.horizontal_fov_deg) + "°";
  if (c.shift_x != 0 || c.shift_y != 0)
    text += "; lens shift " + number(c.shift_x) + " of the width right, " + number(c.shift_y) + " of the height up";
  return text;
}

std::string image_text(const RenderSettings& r) {
  std::string text = std::to_string(r.width) + " × " + std::to_string(r.height) + " pixels; ";
  text += r.integrator == Integrator::path
              ? "path-traced reference, " + std::to_string(r.samples_per_pixel) + " paths per pixel"
              : "the paper's bands method, " + std::to_string(r.samples_per_axis) + " × " +
                    std::to_string(r.samples_per_axis) + " samples per pixel";
  text += "; exposure " + (r.exposure_ev ? "EV " + number(*r.exposure_ev) : std::string("automatic"));
  text += r.human_display ? "; human display" : "; photographic display";
  return text;
}

}  // namespace

std::vector<ConditionRow> scene_conditions(const Scene& scene) {
  return {
      {"Site", site_text(scene)},
      {"Time", scene.time.empty() ? "not given" : scene.time},
      {"Sun", sun_text(scene)},
      {"Weather", weather_text(scene)},
      {"Atmosphere", atmosphere_text(scene.atmosphere)},
      {"Sky", sky_text(scene.atmosphere)},
      {"Fog", fog_text(scene)},
      {"Clouds", clouds_text(scene)},
      {"Lights", scene.lights.empty() ? "none" : std::to_string(scene.lights.size()) + " luminaire(s)"},
      {"Camera and lens", camera_text(scene.camera)},
      {"Image", image_text(scene.render)},
  };
}

}  // namespace skylit
