// skylit: the command-line program. It parses arguments and hands over to one
// subcommand (commands.h). Exit status: 0 done, 2 a problem with the input (one line
// on stderr names the file and the place), 1 an internal error.
#include <optional>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "exit_status.h"
#include "process_group.h"
#include "skylit/io/atomic_file.h"

int main(int argc, char** argv) {
  CLI::App app{
      "skylit: spectral renderer of outdoor scenes under real atmospheric conditions.\n"
      "Images hold absolute luminance (cd/m²). Units: metres, degrees, nanometres."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "skylit " SKYLIT_VERSION);
  // One line, as every other user mistake gets (issue 19, item 15); set before the
  // subcommands are added, which take it over.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "skylit: " + std::string(e.what()) + " (see skylit --help)\n";
  });
  // An interrupted render or sweep leaves no hidden temporary file behind (issue 19, item 14).
  skylit::remove_temporaries_on_signals();
  const std::vector<skylit::cli::CommandRunner> commands = {
      skylit::cli::add_render_command(app),  skylit::cli::add_sun_command(app),
      skylit::cli::add_sky_command(app),     skylit::cli::add_spectrum_command(app),
      skylit::cli::add_sweep_command(app),   skylit::cli::add_compare_command(app),
      skylit::cli::add_info_command(app),    skylit::cli::add_road_command(app),
      skylit::cli::add_animate_command(app),
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    return status == 0 ? 0 : skylit::cli::kExitInputError;
  }
  // Under mpirun: MPI for the whole run (process_group.h); an error on one rank ends all.
  std::optional<skylit::cli::ProcessGroup> processes;
  const int status = skylit::cli::run_with_exit_status([&] {
    processes.emplace(&argc, &argv);
    // Each runner returns -1 when its subcommand was not the one given.
    for (const auto& run : commands)
      if (const int status = run(); status >= 0) return status;
    return 0;
  });
  if (status != 0) skylit::cli::abort_other_processes(status);
  return status;
}
