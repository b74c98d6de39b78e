// The atmosphere options shared by `skylit sky` and `skylit spectrum`, with their units.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "skylit/atmosphere/atmosphere_settings.h"

namespace skylit::cli {

struct AtmosphereOptions {
  double sun_altitude_deg = 0;
  double sun_azimuth_deg = 180;
  double observer_altitude_m = 1.6;
  std::string model = "full";
  std::string aerosol_type = "continental_average";
  std::optional<double> angstrom_exponent;  // replaces the type's two exponents
  AtmosphereSettings settings;
};

// Adds --sun-altitude, --sun-azimuth, --aerosol-type, --aod550, --angstrom, --ozone-du,
// --ground-albedo, --model and --observer-altitude to `command`.
void add_atmosphere_options(CLI::App* command, AtmosphereOptions& options);

// The settings with the model, the aerosol type and its overrides applied.
AtmosphereSettings atmosphere_settings(const AtmosphereOptions& options);

}  // namespace skylit::cli
