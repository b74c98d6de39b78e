#include "atmosphere_options.h"

#include <vector>

#include "number_checks.h"
#include "skylit/atmosphere/aerosol_types.h"

namespace skylit::cli {

void add_atmosphere_options(CLI::App* command, AtmosphereOptions& o) {
  command
      ->add_option("--sun-altitude", o.sun_altitude_deg,
                   "Sun's altitude above the horizon as seen (refraction included, as a scene's), degrees (−90 to 90)")
      ->required()
      ->check(finite_range(-90.0, 90.0));
  command->add_option("--sun-azimuth", o.sun_azimuth_deg, "Sun's azimuth, degrees clockwise from north (default 180)")
      ->check(finite_range(-360.0, 360.0));
  command->add_option("--aod550", o.settings.aerosol.aod_550, "Aerosol optical depth at 550 nm (default 0.1, clear)")
      ->check(finite_range(0.0, 10.0));
  command
      ->add_option("--aerosol-type", o.aerosol_type,
                   "OPAC aerosol type (default continental_average; docs/atmosphere.md)")
      ->check(CLI::IsMember(std::vector<std::string>(aerosol_type_names().begin(), aerosol_type_names().end())));
  command
      ->add_option("--angstrom", o.angstrom_exponent,
                   "Ångström exponent of the aerosols (default: the type's, 1.42 above 500 nm for continental)")
      ->check(finite_range(-1.0, 4.0));
  command->add_option("--ozone-du", o.settings.ozone_column_du, "Total ozone column, Dobson units (default 300)")
      ->check(finite_range(0.0, 1000.0));
  command->add_option("--ground-albedo", o.settings.ground_albedo, "Ground reflectance, 0 to 1 (default 0.15)")
      ->check(finite_range(0.0, 1.0));
  command
      ->add_option("--model", o.model,
                   "full: single and multiple scattering with ozone (default); paper: the paper's single scattering "
                   "without ozone")
      ->check(CLI::IsMember({"full", "paper"}));
  command
      ->add_option("--observer-altitude", o.observer_altitude_m,
                   "Observer's height above the ground, metres (default 1.6, up to 10000 and more)")
      ->check(finite_range(0.0, 90000.0));
}

AtmosphereSettings atmosphere_settings(const AtmosphereOptions& o) {
  AtmosphereSettings settings = o.settings;
  settings.model = o.model == "paper" ? AtmosphereModel::paper : AtmosphereModel::full;
  settings.aerosol = with_aerosol_type(settings.aerosol, *aerosol_type_from_name(o.aerosol_type));
  if (o.angstrom_exponent)
    settings.aerosol.angstrom_exponent = settings.aerosol.angstrom_exponent_short = *o.angstrom_exponent;
  return settings;
}

}  // namespace skylit::cli
