#include "skylit/io/weather/weather_conditions.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/optical_properties.h"
#include "skylit/atmosphere/seen_sun.h"
#include "skylit/clouds/clouds_in_sky.h"
#include "skylit/core/formatted.h"
#include "skylit/io/weather/luminous_efficacy.h"
#include "skylit/spectrum/cie.h"
#include "skylit/sun/solar_position.h"

namespace skylit {

namespace {

// The meteorological definition of fog: a visibility below 1 km (WMO).
constexpr double kFogBelowKm = 1.0;
// Snow on the ground: at least 1 cm covers grass and paving. Its broadband albedo runs
// from about 0.4 (old, wet) to 0.9 (fresh); 0.6 stands for snow of a few days.
constexpr double kSnowDepthCm = 1.0;
constexpr double kSnowAlbedo = 0.6;
// A cloud layer's mid-plane when the file gives no ceiling (or an unlimited one): a
// typical base of low and middle clouds. Ceilings outside 100–12,000 m are not used.
constexpr double kDefaultCloudAltitudeM = 2000.0;
// The bisection's bracket: aod_550 from 0 (no aerosol) to 5 (thick smoke or dust).
constexpr double kMaxFittedAod = 5.0;
// The check's grid of ground points under the clouds (cells on a side; the renderer's
// has up to CloudSkyShare::kMaxCells): their mean is what is compared with the file.
constexpr int kCheckShareCells = 8;
// Up to this opaque cover (tenths / 10) the aerosol is fitted to the beam over the clear
// part of the hour; above it the beam is a mean through moving clouds, the aerosol comes
// from the visibility and the beam gives the sunshine (docs/weather.md, "Cloudy hours":
// on the Amsterdam file the visibility's aerosol spread the diffuse light of 1–3 tenths
// over −46 % to +29 % of the file's, p10 to p90, where the beam fit kept it within −4 %
// and +16 %).
constexpr double kMostCoverForBeamFit = 0.3;
// Below this the beam counts as none (the file's illuminances are whole hundreds of lx).
constexpr double kNoBeamLux = 1.0;

double direct_normal_lux(AtmosphereSettings air, double aod, double sun_elevation_rad) {
  air.aerosol.aod_550 = aod;
  return illuminance(direct_sun_at_ground(air, sun_elevation_rad));
}

// The luminous efficacy (lm/W) the file itself gives a quantity: the median of lux/W m⁻²
// over its hours with both above 50 W m⁻²; empty when there are none.
std::optional<double> file_efficacy(const EpwFile& file, std::optional<double> EpwHour::*lux,
                                    std::optional<double> EpwHour::*watts) {
  std::vector<double> ratios;
  for (const EpwHour& h : file.hours)
    if ((h.*lux) && (h.*watts) && *(h.*watts) > 50) ratios.push_back(*(h.*lux) / *(h.*watts));
  if (ratios.empty()) return std::nullopt;
  std::nth_element(ratios.begin(), ratios.begin() + static_cast<long>(ratios.size() / 2), ratios.end());
  return ratios[ratios.size() / 2];
}

// An efficacy the file does not give, from a model of the hour's sky, and what it is.
struct ModelEfficacy {
  double lm_w;
  std::string source;
};

// The hour's illuminance, or its irradiance times the file's efficacy when the
// illuminance is missing, or else times the model's (said in `decisions`).
std::optional<double> illuminance_of(const EpwFile& file, const EpwHour& hour, std::optional<double> EpwHour::*lux,
                                     std::optional<double> EpwHour::*watts, const char* what,
                                     std::vector<std::string>& decisions,
                                     const std::optional<ModelEfficacy>& model = std::nullopt) {
  if (hour.*lux) return *(hour.*lux);
  if (!(hour.*watts)) return std::nullopt;
  // No light is no light, whatever the efficacy (which, for Perez's, is undefined then):
  // PVGIS files give 0 W/m² and no illuminances, and such hours read as missing and
  // took the scene's clear sky.
  if (*(hour.*watts) == 0) return 0.0;
  if (const std::optional<double> efficacy = file_efficacy(file, lux, watts)) {
    decisions.push_back(std::string(what) + " illuminance missing: the irradiance × the file's median efficacy " +
                        formatted("%.1f lm/W", *efficacy));
    return *(hour.*watts) * *efficacy;
  }
  if (!model) return std::nullopt;
  decisions.push_back(std::string(what) +
                      " illuminance missing, and none in the file to take an efficacy from: the irradiance × " +
                      model->source + formatted(" %.1f lm/W", model->lm_w));
  return *(hour.*watts) * model->lm_w;
}

// Perez et al. (1990)'s efficacies of this hour's sky (io/weather/luminous_efficacy.h),
// for files that give irradiances without illuminances; `water_from` says where the
// precipitable water came from.
std::optional<DaylightEfficacy> hour_efficacy(const EpwHour& hour, double sun_altitude_deg,
                                              double earth_sun_distance_au, std::string& water_from) {
  if (!hour.direct_normal_w_m2 || !hour.diffuse_horizontal_w_m2 || !(sun_altitude_deg > 0)) return std::nullopt;
  double water_cm = 2.0;  // Perez's own default where nothing better is known
  water_from = "2 cm assumed";
  if (hour.precipitable_water_mm) {
    water_cm = *hour.precipitable_water_mm / 10;
    water_from = formatted("%.1f cm from the file", water_cm);
  } else if (hour.dew_point_c) {
    water_cm = precipitable_water_cm_from_dew_point(*hour.dew_point_c);
    water_from = formatted("%.1f cm from the dew point", water_cm);
  }
  return perez_daylight_efficacy(*hour.direct_normal_w_m2, *hour.diffuse_horizontal_w_m2, 90 - sun_altitude_deg,
                                 water_cm, kPerezSolarConstantWm2 / (earth_sun_distance_au * earth_sun_distance_au));
}

void fit_aerosol(AtmosphereSettings& air, double sun_elevation_rad, double target_lux, WeatherSummary& summary) {
  const double clearest = direct_normal_lux(air, 0.0, sun_elevation_rad);
  const double murkiest = direct_normal_lux(air, kMaxFittedAod, sun_elevation_rad);
  if (target_lux >= clearest) {
    air.aerosol.aod_550 = 0;
    summary.decisions.push_back(formatted(
        "aerosol: aod_550 = 0; the file's beam (%.0f lx) is brighter than the model's without aerosol (%.0f lx)",
        target_lux, clearest));
    return;
  }
  if (target_lux <= murkiest) {
    air.aerosol.aod_550 = kMaxFittedAod;
    summary.decisions.push_back(
        formatted("aerosol: aod_550 = %.0f, the bracket's end; the file's beam (%.1f lx) is dimmer still",
                  kMaxFittedAod, target_lux));
    return;
  }
  // The beam falls monotonically with the aerosol: bisection to 1e-6 in aod_550.
  double lo = 0, hi = kMaxFittedAod;
  while (hi - lo > 1e-6) {
    const double mid = 0.5 * (lo + hi);
    (direct_normal_lux(air, mid, sun_elevation_rad) > target_lux ? lo : hi) = mid;
  }
  air.aerosol.aod_550 = 0.5 * (lo + hi);
  summary.decisions.push_back(
      formatted("aerosol: aod_550 = %.4f, fitted by bisection so that the model's direct normal illuminance is %.0f lx",
                air.aerosol.aod_550, target_lux));
}

void aerosol_from_visibility(const EpwHour& hour, AtmosphereSettings& air, WeatherSummary& summary, const char* why) {
  // No observation sees farther than clean air lets it (Koschmieder's range of the
  // Rayleigh extinction alone, about 320 km at 550 nm): files write such values for
  // "unlimited" (999 km in German test reference years, 777.7 and 1600 km in TMYx
  // files), which say nothing of the aerosol and taken literally would leave none at all.
  // The scene's aerosol stays for all of them; below it, values are taken as they are,
  // so that a clearer report never gives a hazier sky. (A cut at 999 km alone made 998
  // km aerosol-free and 999 km the scene's haze.)
  const double clean_air_km = clean_air_visibility_km();
  if (hour.visibility_km && *hour.visibility_km >= clean_air_km) {
    summary.decisions.push_back(
        std::string("aerosol: ") + why +
        formatted("; aod_550 = %.3f as the scene gives it (a visibility of %.0f km, beyond clean air's %.0f km, "
                  "marks it unlimited)",
                  air.aerosol.aod_550, *hour.visibility_km, clean_air_km));
  } else if (hour.visibility_km && *hour.visibility_km >= kFogBelowKm) {
    air.aerosol.aod_550 = aod_550_from_visibility(*hour.visibility_km, air.aerosol.scale_height_m);
    summary.decisions.push_back(
        std::string("aerosol: ") + why +
        formatted("; aod_550 = %.3f from the visibility of %.1f km (haze)", air.aerosol.aod_550, *hour.visibility_km));
  } else {
    summary.decisions.push_back(std::string("aerosol: ") + why +
                                formatted("; aod_550 = %.3f as the scene gives it", air.aerosol.aod_550));
  }
}

// A generated layer's densest cover: a full one would need infinitely many clouds (its
// expected count grows as −ln(1 − coverage)); a sky fully covered with the sun up is
// the overcast CIE sky instead.
constexpr double kMostGeneratedCoverage = 0.95;

CloudLayerSettings cloud_layer_for(const EpwHour& hour, double coverage) {
  CloudLayerSettings layer;
  layer.coverage = std::min(coverage, kMostGeneratedCoverage);
  layer.altitude = hour.ceiling_height_m && *hour.ceiling_height_m >= 100 && *hour.ceiling_height_m <= 12000
                       ? *hour.ceiling_height_m
                       : kDefaultCloudAltitudeM;
  // The same hour of the same date always gets the same clouds.
  layer.seed = static_cast<std::uint64_t>((hour.month * 32 + hour.day) * 25 + hour.hour);
  // A dense layer is made of fewer, larger clouds, so that it stays within the limit.
  for (int grown = 0;
       grown < 40 && expected_generated_cloud_count(layer) > 0.8 * static_cast<double>(kMaxGeneratedClouds); ++grown) {
    layer.min_semi_axis *= 1.25;
    layer.max_semi_axis *= 1.25;
  }
  return layer;
}

}  // namespace

void apply_weather_hour(const EpwFile& file, const EpwHour& hour, Scene& scene,
                        const std::optional<SiteLocation>& scene_site) {
  const EpwLocation& where = file.location;
  WeatherSummary summary;
  summary.file = file.name;
  summary.station = where.city + ", " + where.country + " (" + where.source + " " + where.wmo_station + ")";
  summary.latitude_deg = where.latitude_deg;
  summary.longitude_deg = where.longitude_deg;
  summary.time_zone_h = where.time_zone_h;
  summary.elevation_m = where.elevation_m;
  summary.missing = hour.missing;
  summary.record =
      formatted("%02.0f-%02.0f hour %.0f", hour.month, hour.day, hour.hour) +
      formatted(" (%02.0f:00-%02.0f:00 local standard time), line %.0f", hour.hour - 1, hour.hour, hour.line);

  // The sun at the hour's middle, in the file's standard time.
  OffsetDateTime when;
  when.year = hour.month == 2 && hour.day == 29 && !is_leap_year(hour.year) ? 2000 : hour.year;
  when.year = std::clamp(when.year, kSolarPositionFirstYear, kSolarPositionLastYear);
  when.month = hour.month, when.day = hour.day, when.hour = hour.hour - 1, when.minute = 30;
  when.utc_offset_minutes = static_cast<int>(std::lround(where.time_zone_h * 60));
  SpaOptions options;
  if (hour.pressure_pa) options.pressure_mbar = *hour.pressure_pa / 100;
  if (hour.dry_bulb_c) options.temperature_c = *hour.dry_bulb_c;
  const SiteLocation site =
      scene_site ? *scene_site
                 : SiteLocation{where.latitude_deg, where.longitude_deg, std::clamp(where.elevation_m, -500.0, 9000.0)};
  summary.station_distance_km = surface_distance_km(site, {where.latitude_deg, where.longitude_deg, 0});
  const SolarPosition sun = solar_position(site, when, options);
  scene.sun.altitude_deg = sun.altitude_deg;
  scene.sun.azimuth_deg = sun.azimuth_deg;
  summary.sun_altitude_deg = sun.altitude_deg;
  summary.sun_time = formatted("%04.0f-%02.0f-%02.0f", when.year, when.month, when.day) +
                     formatted("T%02.0f:30%+03.0f:%02.0f", when.hour, std::trunc(where.time_zone_h),
                               std::abs(when.utc_offset_minutes % 60));
  scene.site = site;  // for the report's conditions and a city model's frame
  scene.time = summary.sun_time;
  AtmosphereSettings& air = scene.atmosphere;
  air.site_elevation_m = site.elevation_m;
  air.earth_sun_distance_au = sun.earth_sun_distance_au;

  std::vector<std::string>& decisions = summary.decisions;
  std::string water_from;
  const std::optional<DaylightEfficacy> perez =
      hour_efficacy(hour, sun.altitude_deg, sun.earth_sun_distance_au, water_from);
  const std::string perez_source =
      perez ? formatted(
                  "Perez et al. (1990)'s efficacy for this hour's sky (clearness %.2f, brightness %.3f, "
                  "precipitable water ",
                  perez->clearness, perez->brightness) +
                  water_from + ")"
            : std::string();
  auto perez_of = [&](double DaylightEfficacy::*efficacy) -> std::optional<ModelEfficacy> {
    if (!perez) return std::nullopt;
    return ModelEfficacy{(*perez).*efficacy, perez_source};
  };
  summary.file_direct_normal_lux = illuminance_of(file, hour, &EpwHour::direct_normal_lux, &EpwHour::direct_normal_w_m2,
                                                  "direct normal", decisions, perez_of(&DaylightEfficacy::direct_lm_w));
  summary.file_diffuse_horizontal_lux =
      illuminance_of(file, hour, &EpwHour::diffuse_horizontal_lux, &EpwHour::diffuse_horizontal_w_m2,
                     "diffuse horizontal", decisions, perez_of(&DaylightEfficacy::diffuse_lm_w));
  summary.file_global_horizontal_lux =
      illuminance_of(file, hour, &EpwHour::global_horizontal_lux, &EpwHour::global_horizontal_w_m2, "global horizontal",
                     decisions, perez_of(&DaylightEfficacy::global_lm_w));

  const std::optional<double> cover =
      hour.opaque_sky_cover_tenths ? hour.opaque_sky_cover_tenths : hour.total_sky_cover_tenths;
  // Opaque cover is part of the total: more of it is a slip of the file's, said here.
  if (hour.opaque_sky_cover_tenths && hour.total_sky_cover_tenths &&
      *hour.opaque_sky_cover_tenths > *hour.total_sky_cover_tenths)
    decisions.push_back(
        formatted("sky cover: the opaque cover (%.0f tenths) exceeds the total (%.0f) in this record; "
                  "the opaque cover is used",
                  *hour.opaque_sky_cover_tenths, *hour.total_sky_cover_tenths));
  const double coverage = cover ? *cover / 10.0 : 0.0;
  summary.clear_fraction = 1.0 - coverage;
  const double sun_elevation = radians(sun.altitude_deg);
  bool overcast = false;
  std::string overcast_because;
  if (sun.altitude_deg <= 0) {
    aerosol_from_visibility(hour, air, summary, "the sun is below the horizon at the hour's middle");
  } else if (!summary.file_direct_normal_lux) {
    aerosol_from_visibility(hour, air, summary, "no direct normal illuminance or irradiance in this record");
  } else if (*summary.file_direct_normal_lux < kNoBeamLux || summary.clear_fraction <= 0) {
    overcast = true;
    overcast_because = *summary.file_direct_normal_lux < kNoBeamLux
                           ? "no direct beam with the sun up"
                           : formatted("the sky all covered, its %.0f lx of direct beam notwithstanding",
                                       *summary.file_direct_normal_lux);
    aerosol_from_visibility(hour, air, summary, overcast_because.c_str());
  } else if (coverage <= kMostCoverForBeamFit) {
    // A clear or lightly clouded hour: the sun was seldom hidden, and its beam is the
    // clear air's over the clear part of the hour (a small correction here).
    fit_aerosol(air, sun_elevation, *summary.file_direct_normal_lux / summary.clear_fraction, summary);
  } else {
    // A cloudy hour: its beam is a mean over an hour of moving clouds, in which the sun
    // shone some unknown part (not the clear part of the sky: a sun behind a 1/10 cover
    // may never be hidden, one behind 9/10 shine only a few minutes, and thin edges dim
    // it). The air's haze comes from the visibility, as on overcast hours; the beam then
    // says how much of the hour the sun shone. A beam brighter than that air lets through
    // for the whole hour means clearer air: the aerosol is fitted to it, the sun out all
    // hour (the beam bounds the aerosol from above in any case).
    aerosol_from_visibility(hour, air, summary, "a cloudy hour: its beam is a mean through moving clouds");
    const double clear_beam = direct_normal_lux(air, air.aerosol.aod_550, sun_elevation);
    if (*summary.file_direct_normal_lux >= clear_beam) {
      summary.decisions.push_back(formatted(
          "aerosol: the file's beam (%.0f lx) exceeds what that air lets through (%.0f lx) with the sun out all hour",
          *summary.file_direct_normal_lux, clear_beam));
      fit_aerosol(air, sun_elevation, *summary.file_direct_normal_lux, summary);
      summary.clear_fraction = 1;
    } else {
      summary.clear_fraction = *summary.file_direct_normal_lux / clear_beam;
      summary.decisions.push_back(formatted(
          "sunshine: the sun shone %.0f %% of the hour (the file's beam, %.0f lx, over the clear air's, %.0f lx)",
          100 * summary.clear_fraction, *summary.file_direct_normal_lux, clear_beam));
    }
  }

  if (overcast && summary.file_diffuse_horizontal_lux) {
    summary.clear_fraction = 0;
    if (!air.cie_sky) air.cie_sky = CieSkySettings{1, *summary.file_diffuse_horizontal_lux, false};
    air.cie_sky->diffuse_horizontal_lux = *summary.file_diffuse_horizontal_lux;
    decisions.push_back(
        "sky: overcast (" + overcast_because +
        formatted("): CIE standard sky type %.0f scaled to the file's diffuse horizontal illuminance, %.0f lx; "
                  "no cloud geometry",
                  air.cie_sky->type, air.cie_sky->diffuse_horizontal_lux));
  } else if (air.cie_sky && summary.file_diffuse_horizontal_lux) {
    air.cie_sky->diffuse_horizontal_lux = *summary.file_diffuse_horizontal_lux;
    decisions.push_back(formatted("sky: CIE standard sky type %.0f (the scene's) scaled to the file's %.0f lx",
                                  air.cie_sky->type, air.cie_sky->diffuse_horizontal_lux));
  } else if (air.cie_sky) {
    decisions.push_back(
        formatted("sky: CIE standard sky type %.0f at %.0f lx (the scene's or the default: the file "
                  "gives no diffuse horizontal illuminance this hour)",
                  air.cie_sky->type, air.cie_sky->diffuse_horizontal_lux));
  } else if (coverage > 0 && scene.clouds.empty() && !scene.cloud_layer) {
    scene.cloud_layer = cloud_layer_for(hour, coverage);
    decisions.push_back(formatted("clouds: a generated layer covering %.0f %% of the sky at %.0f m, seed %.0f",
                                  100 * scene.cloud_layer->coverage, scene.cloud_layer->altitude,
                                  static_cast<double>(scene.cloud_layer->seed)));
    if (sun.altitude_deg > 0 && summary.file_diffuse_horizontal_lux) {
      scene.cloud_layer->diffuse_horizontal_lux = *summary.file_diffuse_horizontal_lux;
      decisions.push_back(
          formatted("clouds: the share of the sun's and the sky's light that reaches them fitted, "
                    "where they are placed under the sky, to the file's %.0f lx of diffuse light",
                    *summary.file_diffuse_horizontal_lux));
    }
  }

  if (hour.visibility_km && *hour.visibility_km < kFogBelowKm && !scene.fog) {
    FogSettings fog;
    fog.ground_visibility_m = std::max(1.0, *hour.visibility_km * 1000.0);
    scene.fog = fog;
    decisions.push_back(formatted("fog: visibility %.0f m at the ground (below 1 km)", *fog.ground_visibility_m));
  }

  if (hour.snow_depth_cm && *hour.snow_depth_cm >= kSnowDepthCm) {
    air.ground_albedo = kSnowAlbedo;
    decisions.push_back(formatted("ground: %.0f cm of snow, albedo %.2f", *hour.snow_depth_cm, kSnowAlbedo));
  } else if (hour.albedo && *hour.albedo > 0) {
    air.ground_albedo = *hour.albedo;
    decisions.push_back(formatted("ground: albedo %.2f from the file", *hour.albedo));
  } else {
    decisions.push_back(formatted("ground: no snow; albedo %.2f as the scene gives it", air.ground_albedo));
  }
  scene.weather = std::move(summary);
}

void check_weather_model(Scene& scene) {
  if (!scene.weather) return;
  WeatherSummary& w = *scene.weather;
  const Vec3 to_sun = direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg);
  const Atmosphere atmosphere(scene.atmosphere);
  const SkyModel sky(atmosphere, SunRefraction(atmosphere).true_direction(to_sun), 1.0);
  const double beam = illuminance(sky.direct_sun(0.0)) * w.clear_fraction;
  w.model_direct_normal_lux = beam;
  w.model_diffuse_horizontal_lux = illuminance(sky.sky_irradiance({0, 0, 1}));
  w.clear_sky_diffuse_horizontal_lux = w.model_diffuse_horizontal_lux;
  // The clouds as the renderer sees them: the clouded sky's light on the open ground,
  // averaged over a grid around the site (the clouds drift over a point in an hour).
  if (!scene.clouds.empty() || scene.cloud_layer) {
    const CloudsInSky clouds(scene.clouds, scene.cloud_layer, sky, {0, 0, 0}, scene.render.cloud_light,
                             kCheckShareCells);
    w.model_diffuse_horizontal_lux = illuminance(clouds.sky_share_grid().mean_irradiance_up());
    if (scene.cloud_layer && scene.cloud_layer->diffuse_horizontal_lux) {
      w.decisions.push_back(formatted("clouds: lit by %.2f of the sun's and the sky's light", clouds.light_share()));
      if (clouds.light_share() != clouds.fitted_light_share())
        w.decisions.push_back(
            formatted("clouds: the share that would give the file's diffuse light, %.2f, lies "
                      "outside [%.2f, %.2f]",
                      clouds.fitted_light_share(), kLeastCloudLightShare, kMostCloudLightShare));
    }
  }
  w.model_global_horizontal_lux = *w.model_diffuse_horizontal_lux + beam * std::max(0.0, to_sun.z);
}

namespace {

std::string compared(const char* what, const std::optional<double>& file, const std::optional<double>& model,
                     double tolerance) {
  std::string line = std::string("  ") + what + ": ";
  if (!file) return line + "not in the file\n";
  if (!model) return line + formatted("file %.0f lx\n", *file);
  line += formatted("file %.0f lx, model %.0f lx", *file, *model);
  if (*file <= 0) return line + "\n";
  const double error = *model / *file - 1.0;
  return line + formatted(" (%+.1f %%, tolerance %.0f %%: ", 100 * error, 100 * tolerance) +
         (std::abs(error) <= tolerance ? "within)\n" : "OUTSIDE)\n");
}

}  // namespace

std::string describe_weather(const WeatherSummary& w) {
  std::string text = "weather: " + w.file + ": " + w.station + "\n";
  text += formatted("  station %.3f, %.3f", w.latitude_deg, w.longitude_deg) +
          formatted(", elevation %.1f m, time zone UTC%+.1f h", w.elevation_m, w.time_zone_h) +
          (w.station_distance_km > 0.05 ? formatted(", %.1f km from the site\n", w.station_distance_km) : "\n");
  text += "  record " + w.record + "; sun at " + w.sun_time +
          formatted(", altitude %.2f deg (seen from the site)\n", w.sun_altitude_deg);
  if (!w.missing.empty()) {
    text += "  missing or out of range in this record:";
    for (size_t i = 0; i < w.missing.size(); ++i) text += (i ? ", " : " ") + w.missing[i];
    text += "\n";
  }
  for (const std::string& d : w.decisions) text += "  " + d + "\n";
  text += formatted("  check (photopic, lx; direct beam over %.0f %% of the hour", 100 * w.clear_fraction) +
          (w.clear_sky_diffuse_horizontal_lux && w.model_diffuse_horizontal_lux &&
                   *w.clear_sky_diffuse_horizontal_lux != *w.model_diffuse_horizontal_lux
               ? formatted("; diffuse with the clouds, %.0f lx without):\n", *w.clear_sky_diffuse_horizontal_lux)
               : std::string("):\n"));
  text += compared("direct normal", w.file_direct_normal_lux, w.model_direct_normal_lux, kWeatherDirectNormalTolerance);
  text += compared("diffuse horizontal", w.file_diffuse_horizontal_lux, w.model_diffuse_horizontal_lux,
                   kWeatherDiffuseHorizontalTolerance);
  text += compared("global horizontal", w.file_global_horizontal_lux, w.model_global_horizontal_lux,
                   kWeatherGlobalHorizontalTolerance);
  return text;
}

}  // namespace skylit
