// One hour of a weather file made into a scene's site, sun, air, sky, clouds, fog and
// ground (docs/weather.md says each choice and why):
//
// - site and time zone from the LOCATION line; the sun at the middle of the record's
//   hour (the record holds the hour's means, and the middle is the instant whose sun
//   best stands for them);
// - up to 3/10 opaque cover, the aerosol optical depth at 550 nm fitted by bisection so
//   that the model's direct normal illuminance (380–780 nm weighted by V(λ), the band
//   skylit renders) equals the file's, divided by the clear part of the hour (1 − opaque
//   sky cover); above it the aerosol from the visibility, and the file's beam over the
//   clear air's as the part of the hour the sun shone (the beam is a mean through moving
//   clouds);
// - no direct beam while the sun is up (overcast): the CIE standard overcast sky (type 1)
//   scaled to the file's diffuse horizontal illuminance, and no cloud geometry;
// - otherwise a generated cloud layer covering the opaque sky cover, at the ceiling
//   height (or 2000 m), its seed made from the date and hour, the share of the sun's and
//   the sky's light that reaches its clouds fitted to the file's diffuse horizontal
//   illuminance (clouds/clouds_in_sky.h);
// - fog below 1 km of visibility (the meteorological definition of fog);
// - snow on the ground from the snow depth (ground albedo 0.6), else the file's albedo.
#pragma once

#include "skylit/io/weather/epw_reader.h"
#include "skylit/scene/scene.h"

namespace skylit {

// Sets scene.site, scene.sun, scene.atmosphere (site elevation, Earth–Sun distance,
// aod_550, ground albedo, a CIE sky when overcast), scene.cloud_layer and scene.fog
// (unless the scene gives its own clouds or fog) and scene.weather. The sun stands as
// seen from `site` (the scene's own, or a city model's centre) at the record's instant,
// else from the file's station: a station tens of kilometres away has the same weather
// but sees the sun elsewhere, and a city model is placed around the site, not the
// station.
void apply_weather_hour(const EpwFile& file, const EpwHour& hour, Scene& scene,
                        const std::optional<SiteLocation>& site = std::nullopt);

// Fills scene.weather's model values: the model's direct normal, diffuse and global
// horizontal illuminance for the scene's air, sky and clouds (the clouded sky as the
// renderer sees it, averaged over a grid of ground points around the site; the beam
// over the part of the hour the sun shone). Builds the sky's tables (about a second)
// and, under clouds, places them (a few seconds).
void check_weather_model(Scene& scene);

// For `skylit info`: the station, the record, the sun's instant, the missing fields, each
// decision, and the model against the file with the tolerances (weather_summary.h).
std::string describe_weather(const WeatherSummary& weather);

}  // namespace skylit
