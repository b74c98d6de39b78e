// The program's subcommands. Each registers itself on the CLI11 app and returns the
// function that runs it once the arguments are parsed (exit status as exit_status.h).
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

#include "skylit/scene/scene.h"

namespace skylit::cli {

using CommandRunner = std::function<int()>;

// `skylit render SCENE -o OUT ...`
CommandRunner add_render_command(CLI::App& app);

// `skylit sun --lat DEG --lon DEG --time ISO8601 [--json]`
CommandRunner add_sun_command(CLI::App& app);

// `skylit sky --sun-altitude DEG ... --projection fisheye|equirect --size N -o OUT`
CommandRunner add_sky_command(CLI::App& app);

// `skylit spectrum --sun-altitude DEG ... [--csv] [--plot FILE]`
CommandRunner add_spectrum_command(CLI::App& app);

// `skylit sweep SCENE --vary PATH=V1,V2,... [--vary ...] -o SHEET.png` (docs/sweeps.md)
CommandRunner add_sweep_command(CLI::App& app);

// `skylit animate SCENE -o FOLDER (--from T --to T [--every STEP] | --dates D,... --at hh:mm)` (docs/animations.md)
CommandRunner add_animate_command(CLI::App& app);

// `skylit compare A B [--regions R.json] [--mask M.png] [--standard-error-a SA] [--standard-error-b SB]
// [-o RATIO.png] [--json OUT.json]` (docs/validation.md)
CommandRunner add_compare_command(CLI::App& app);

// `skylit info SCENE [--set PATH=VALUE ...]`: what the scene loads, and warnings
CommandRunner add_info_command(CLI::App& app);

// `skylit road SCENE [--set PATH=VALUE ...] [--json]`: EN 13201-3 figures (docs/road-lighting.md)
CommandRunner add_road_command(CLI::App& app);

// The scene's warnings (io/scene/scene_report.h) on stderr, one "skylit: warning:" line each.
void print_scene_warnings(const Scene& scene, bool check_camera);

}  // namespace skylit::cli
