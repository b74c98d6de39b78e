// The `site`, `time`, `sun` and `atmosphere` parts of a scene file: where and when the
// scene is, where the sun stands, and what the air is like.
#include <cmath>

#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/optical_properties.h"
#include "skylit/io/scene/scene_parts.h"
#include "skylit/sun/solar_position.h"

namespace skylit {

namespace {

SiteLocation read_site(const JsonReader& j) {
  j.allow_only({"latitude_deg", "longitude_deg", "elevation_m"});
  SiteLocation site;
  site.latitude_deg = j.required("latitude_deg").number_in(-90, 90);
  site.longitude_deg = j.required("longitude_deg").number_in(-180, 180);
  if (auto e = j.optional("elevation_m")) site.elevation_m = e->number_in(-500, 9000);
  return site;
}

}  // namespace

std::optional<SiteLocation> read_scene_site(const JsonReader& root) {
  if (auto site = root.optional("site")) return read_site(*site);
  return std::nullopt;
}

bool read_sun_and_atmosphere(const JsonReader& root, Scene& scene) {
  const auto sun = root.optional("sun");
  const auto site = root.optional("site");
  const auto time = root.optional("time");
  if (auto a = root.optional("atmosphere")) scene.atmosphere = read_atmosphere(*a);

  if (site) {
    scene.site = read_site(*site);
    scene.atmosphere.site_elevation_m = scene.site->elevation_m;
  }
  if (sun && time) sun->fail("give either the sun's position or a site and a time, not both");
  if (!sun && !time) root.fail("missing 'sun' (altitude_deg, azimuth_deg), or 'site' and 'time'");

  if (sun) {
    sun->allow_only({"altitude_deg", "azimuth_deg"});
    scene.sun.altitude_deg = sun->required("altitude_deg").number_in(-90, 90);
    scene.sun.azimuth_deg = sun->required("azimuth_deg").number_in(-360, 360);
    return false;
  }
  const OffsetDateTime when = parse_offset_date_time(time->string(), time->source() + ": " + time->path());
  if (when.year < kSolarPositionFirstYear || when.year > kSolarPositionLastYear)
    time->fail_expected("a year from " + std::to_string(kSolarPositionFirstYear) + " to " +
                        std::to_string(kSolarPositionLastYear));
  if (!site) return true;  // a city model may give the site
  place_sun(root, read_site(*site), scene);
  return false;
}

void place_sun(const JsonReader& root, const std::optional<SiteLocation>& site, Scene& scene) {
  const JsonReader time = root.required("time");
  if (!site) time.fail("a time needs a site (latitude_deg, longitude_deg) to place the sun");
  scene.site = site;
  scene.atmosphere.site_elevation_m = site->elevation_m;
  const SolarPosition position =
      solar_position(*site, parse_offset_date_time(time.string(), time.source() + ": " + time.path()));
  scene.site = site;
  scene.time = time.string();
  scene.sun.altitude_deg = position.altitude_deg;
  scene.sun.azimuth_deg = position.azimuth_deg;
  scene.atmosphere.earth_sun_distance_au = position.earth_sun_distance_au;
}

AtmosphereSettings read_atmosphere(const JsonReader& j) {
  j.allow_only({"model", "multiple_scattering", "air_density", "aerosol_type", "aod_550", "visibility_km",
                "linke_turbidity", "angstrom_exponent", "single_scattering_albedo", "asymmetry", "aerosol_phase",
                "aerosol_scale_height_m", "ozone_du", "ground_albedo", "refraction"});
  AtmosphereSettings a;
  if (auto m = j.optional("model"))
    a.model = m->one_of({"full", "paper"}) == "paper" ? AtmosphereModel::paper : AtmosphereModel::full;
  if (auto m = j.optional("multiple_scattering"))
    a.multiple_scattering = m->one_of({"scattering_orders", "hillaire"}) == "hillaire"
                                ? MultipleScatteringMethod::hillaire
                                : MultipleScatteringMethod::scattering_orders;
  if (auto d = j.optional("air_density"))
    a.air_density = d->one_of({"us_standard_1976", "exponential"}) == "exponential" ? AirDensity::exponential
                                                                                    : AirDensity::us_standard_1976;
  if (auto t = j.optional("aerosol_type")) {
    a.aerosol = with_aerosol_type(a.aerosol, *aerosol_type_from_name(t->one_of(aerosol_type_names())));
  }
  if (auto h = j.optional("aerosol_scale_height_m")) a.aerosol.scale_height_m = h->number_in(100, 20000);
  const int turbidity_keys = j.has("aod_550") + j.has("visibility_km") + j.has("linke_turbidity");
  if (turbidity_keys > 1) j.fail("give one of aod_550, visibility_km, linke_turbidity");
  if (auto t = j.optional("aod_550")) a.aerosol.aod_550 = t->number_in(0, 10);
  if (auto v = j.optional("visibility_km"))
    a.aerosol.aod_550 = aod_550_from_visibility(v->number_in(0.05, 1000), a.aerosol.scale_height_m);
  if (auto l = j.optional("linke_turbidity")) a.aerosol.aod_550 = aod_550_from_linke_turbidity(l->number_in(1, 12));
  // One exponent given replaces both of the type's pieces.
  if (auto e = j.optional("angstrom_exponent"))
    a.aerosol.angstrom_exponent = a.aerosol.angstrom_exponent_short = e->number_in(-1, 4);
  if (auto w = j.optional("single_scattering_albedo")) a.aerosol.single_scattering_albedo = w->number_in(0, 1);
  if (auto g = j.optional("asymmetry")) a.aerosol.asymmetry = g->number_in(0, 0.95);
  if (auto p = j.optional("aerosol_phase"))
    a.aerosol.phase = p->one_of({"cornette_shanks", "henyey_greenstein"}) == "cornette_shanks"
                          ? AerosolPhase::cornette_shanks
                          : AerosolPhase::henyey_greenstein;
  if (auto o = j.optional("ozone_du")) a.ozone_column_du = o->number_in(0, 1000);
  if (auto g = j.optional("ground_albedo")) a.ground_albedo = g->number_in(0, 1);
  if (auto r = j.optional("refraction")) a.refraction = r->boolean();
  return a;
}

}  // namespace skylit
