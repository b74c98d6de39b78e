// `skylit info SCENE`: what the scene file loads (per object its file, triangles,
// materials and extent) on stdout, and warnings about likely mistakes on stderr. The
// exit status stays 0 with warnings: the scene is valid.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_report.h"
#include "skylit/io/weather/weather_conditions.h"

namespace skylit::cli {

void print_scene_warnings(const Scene& scene, bool check_camera) {
  for (const std::string& w : scene_warnings(scene, check_camera))
    std::fprintf(stderr, "skylit: warning: %s\n", w.c_str());
}

namespace {

struct InfoArguments {
  std::string scene_file;
  std::vector<std::string> overrides;
};

int run_info(const InfoArguments& args) {
  Scene scene = load_scene(args.scene_file, args.overrides);
  std::fputs(describe_objects(scene).c_str(), stdout);
  std::fputs(describe_lights(scene).c_str(), stdout);
  if (scene.weather) {
    check_weather_model(scene);
    std::fputs(describe_weather(*scene.weather).c_str(), stdout);
  }
  std::fflush(stdout);
  print_scene_warnings(scene, /*check_camera=*/true);
  return 0;
}

}  // namespace

CommandRunner add_info_command(CLI::App& app) {
  auto args = std::make_shared<InfoArguments>();
  CLI::App* info = app.add_subcommand(
      "info",
      "Say what a scene file loads: per object its file, triangles, materials and extent; warn about likely "
      "mistakes (on stderr; the exit status stays 0).");
  info->add_option("scene", args->scene_file, "Scene file (JSON; see docs/scene-format.md)")->required();
  info->add_option("--set", args->overrides, "Override a scene value: PATH=VALUE, as for render");
  return [info, args] { return info->parsed() ? run_info(*args) : -1; };
}

}  // namespace skylit::cli
