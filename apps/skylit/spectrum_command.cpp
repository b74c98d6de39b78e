// `skylit spectrum`: direct, diffuse and zenith spectra at 1 nm from the atmosphere model.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "atmosphere_options.h"
#include "commands.h"
#include "skylit/atmosphere/solar_spectrum.h"
#include "skylit/core/angles.h"
#include "skylit/figures/plot.h"
#include "skylit/spectrum/cie.h"

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

// The spectra's photometric sums (683 lm/W × Σ ȳ(λ) · 1 nm): what a lighting designer
// reads first, printed when neither the CSV nor a plot is asked for.
void print_illuminances(const std::vector<SolarSpectrumSample>& samples, const SpectrumArguments& args) {
  double direct = 0, diffuse = 0, zenith = 0;
  for (const SolarSpectrumSample& s : samples) {
    const double y = cie1931().y(s.wavelength_nm) * kMaxLuminousEfficacy;
    direct += y * s.direct_normal;
    diffuse += y * s.diffuse_horizontal;
    zenith += y * s.zenith_radiance;
  }
  const double seen_altitude = radians(args.atmosphere.sun_altitude_deg);
  const double global = diffuse + direct * std::max(0.0, std::sin(seen_altitude));
  std::printf("sun seen at %.2f° (%s model, aod550 %.3g)\n", args.atmosphere.sun_altitude_deg,
              args.atmosphere.model.c_str(), args.atmosphere.settings.aerosol.aod_550);
  std::printf("direct normal illuminance       %.6g lx\n", direct);
  std::printf("diffuse horizontal illuminance  %.6g lx\n", diffuse);
  std::printf("global horizontal illuminance   %.6g lx\n", global);
  std::printf("zenith luminance                %.6g cd/m²\n", zenith);
}

int run_spectrum(const SpectrumArguments& args) {
  const std::vector<SolarSpectrumSample> samples =
      solar_spectrum(atmosphere_settings(args.atmosphere),
                     direction_from_altitude_azimuth(args.atmosphere.sun_altitude_deg, args.atmosphere.sun_azimuth_deg),
                     args.atmosphere.observer_altitude_m);
  if (!args.plot.empty()) write_spectrum_plot(samples, args);
  if (!args.csv && args.plot.empty()) print_illuminances(samples, args);
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
      "spectrum",
      "Direct normal and diffuse horizontal irradiance and zenith radiance, 380–780 nm at 1 nm (without --csv or "
      "--plot: their illuminances and luminance).");
  add_atmosphere_options(spectrum, args->atmosphere);
  spectrum->add_flag("--csv", args->csv,
                     "Print CSV: wavelength_nm, direct_normal_W_m2_nm, diffuse_horizontal_W_m2_nm, "
                     "zenith_radiance_W_m2_sr_nm");
  spectrum->add_option("--plot", args->plot, "Draw the three spectra into FILE.svg or FILE.png");
  return [spectrum, args] { return spectrum->parsed() ? run_spectrum(*args) : -1; };
}

}  // namespace skylit::cli
