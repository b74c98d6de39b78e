// `skylit spectrum`: direct, diffuse and zenith spectra at 1 nm from the atmosphere model.
#include <cstdio>
#include <memory>
#include <string>

#include "atmosphere_options.h"
#include "commands.h"
#include "skylit/atmosphere/solar_spectrum.h"
#include "skylit/figures/plot.h"

namespace skylit::cli {

namespace {

struct SpectrumArguments {
  AtmosphereOptions atmosphere;
  bool csv = false;
  std::string plot;
};

void write_spectrum_plot(const std::vector<SolarSpectrumSample>& samples, const SpectrumArguments& args) {
  Plot plot;
  char title[160];
  std::snprintf(title, sizeof title, "Sun at %.1f° altitude, aod550 %.2f, %s model", args.atmosphere.sun_altitude_deg,
                args.atmosphere.settings.aerosol.aod_550, args.atmosphere.model.c_str());
  plot.title = title;
  plot.x_label = "wavelength (nm)";
  plot.y_label = "irradiance (W m⁻² nm⁻¹)";
  plot.y2_label = "radiance (W m⁻² sr⁻¹ nm⁻¹)";
  PlotSeries direct{"direct normal irradiance", {}, {}, false};
  PlotSeries diffuse{"diffuse horizontal irradiance", {}, {}, false};
  PlotSeries zenith{"zenith radiance", {}, {}, true};
  for (const SolarSpectrumSample& s : samples) {
    for (PlotSeries* series : {&direct, &diffuse, &zenith}) series->x.push_back(s.wavelength_nm);
    direct.y.push_back(s.direct_normal);
    diffuse.y.push_back(s.diffuse_horizontal);
    zenith.y.push_back(s.zenith_radiance);
  }
  plot.series = {direct, diffuse, zenith};
  write_plot(plot, args.plot);
}

int run_spectrum(const SpectrumArguments& args) {
  const std::vector<SolarSpectrumSample> samples =
      solar_spectrum(atmosphere_settings(args.atmosphere),
                     direction_from_altitude_azimuth(args.atmosphere.sun_altitude_deg, args.atmosphere.sun_azimuth_deg),
                     args.atmosphere.observer_altitude_m);
  if (!args.plot.empty()) write_spectrum_plot(samples, args);
  if (args.csv) {
    std::printf("wavelength_nm,direct_normal_W_m2_nm,diffuse_horizontal_W_m2_nm,zenith_radiance_W_m2_sr_nm\n");
    for (const SolarSpectrumSample& s : samples)
      std::printf("%.0f,%.6g,%.6g,%.6g\n", s.wavelength_nm, s.direct_normal, s.diffuse_horizontal, s.zenith_radiance);
  }
  return 0;
}

}  // namespace

CommandRunner add_spectrum_command(CLI::App& app) {
  auto args = std::make_shared<SpectrumArguments>();
  CLI::App* spectrum = app.add_subcommand(
      "spectrum", "Direct normal and diffuse horizontal irradiance and zenith radiance, 380–780 nm at 1 nm.");
  add_atmosphere_options(spectrum, args->atmosphere);
  spectrum->add_flag("--csv", args->csv,
                     "Print CSV: wavelength_nm, direct_normal_W_m2_nm, diffuse_horizontal_W_m2_nm, "
                     "zenith_radiance_W_m2_sr_nm");
  spectrum->add_option("--plot", args->plot, "Draw the three spectra into FILE.svg or FILE.png");
  return [spectrum, args] { return spectrum->parsed() ? run_spectrum(*args) : -1; };
}

}  // namespace skylit::cli
