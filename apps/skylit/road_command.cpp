// `skylit road SCENE`: the EN 13201-3 figures of the road a scene's `road_lighting`
// block describes, lit by the scene's lamps and shadowed by its objects
// (assess/road_lighting.h, docs/road-lighting.md). A table on stdout, or JSON.
#include <fnmatch.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "skylit/assess/road_lighting.h"
#include "skylit/core/error.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit::cli {

namespace {

struct RoadArguments {
  std::string scene_file;
  std::vector<std::string> overrides;
  bool json = false;
  std::string lights = "*";
};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string json_array(const std::vector<double>& values) {
  std::string out = "[";
  for (size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + number(values[i]);
  return out + "]";
}

std::string as_json(const RoadLightingSettings& road, const RoadLightingFigures& f) {
  std::string observers = "[";
  for (size_t i = 0; i < f.luminance_by_observer.size(); ++i)
    observers += (i ? ", " : "") + json_array(f.luminance_by_observer[i]);
  observers += "]";
  return "{\"r_table\": \"" + road.r_table->name() + "\", \"q0\": " + number(road.q0) +
         ", \"average_luminance_cd_m2\": " + number(f.average_luminance) +
         ", \"overall_uniformity\": " + number(f.overall_uniformity) +
         ", \"longitudinal_uniformity\": " + number(f.longitudinal_uniformity) +
         ", \"threshold_increment_pct\": " + number(f.threshold_increment_pct) +
         ", \"edge_illuminance_ratio\": " + number(f.edge_illuminance_ratio) +
         ", \"average_illuminance_lx\": " + number(f.average_illuminance) +
         ", \"minimum_illuminance_lx\": " + number(f.minimum_illuminance) + ", \"rows\": " + std::to_string(f.rows) +
         ", \"luminance_columns\": " + std::to_string(f.luminance_columns) +
         ", \"illuminance_columns\": " + std::to_string(f.illuminance_columns) +
         ", \"luminance_by_observer_cd_m2\": " + observers + ", \"illuminance_lx\": " + json_array(f.illuminance) +
         "}\n";
}

int run_road(const RoadArguments& args) {
  const Scene scene = load_scene(args.scene_file, args.overrides);
  if (!scene.road_lighting)
    throw InputError(args.scene_file + ": no road_lighting block: give the road to assess (docs/road-lighting.md)");
  // The installation: the lights whose names match (a car's headlights are not part of it).
  std::vector<SceneLight> lights;
  for (const SceneLight& light : scene.lights)
    if (fnmatch(args.lights.c_str(), light.name.c_str(), 0) == 0) lights.push_back(light);
  if (lights.empty())
    throw InputError(args.scene_file + ": no lights or lamp_rows " +
                     (args.lights == "*" ? std::string("to light the road") : "match --lights '" + args.lights + "'"));
  RayTracer occluders;
  for (const SceneObject& object : scene.objects) occluders.add_mesh(object.mesh);
  occluders.commit();
  const RoadLightingSettings& road = *scene.road_lighting;
  const RoadLightingFigures f = compute_road_lighting(road, lights, &occluders);
  if (args.json) {
    std::fputs(as_json(road, f).c_str(), stdout);
    return 0;
  }
  std::printf("road surface %s, Q0 %.3f; grid %d × %d (luminance), %d × %d (illuminance)\n",
              road.r_table->name().c_str(), road.q0, f.rows, f.luminance_columns, f.rows, f.illuminance_columns);
  std::printf("L_av   %8.3f cd/m²\n", f.average_luminance);
  std::printf("U_o    %8.3f\n", f.overall_uniformity);
  std::printf("U_l    %8.3f\n", f.longitudinal_uniformity);
  std::printf("TI     %8.1f %%\n", f.threshold_increment_pct);
  std::printf("R_EI   %8.3f\n", f.edge_illuminance_ratio);
  std::printf("E_av   %8.2f lx\n", f.average_illuminance);
  std::printf("E_min  %8.2f lx\n", f.minimum_illuminance);
  return 0;
}

}  // namespace

CommandRunner add_road_command(CLI::App& app) {
  auto args = std::make_shared<RoadArguments>();
  CLI::App* road = app.add_subcommand(
      "road",
      "Road-lighting figures after EN 13201-3 (L_av, U_o, U_l, TI, R_EI, E_av, E_min) for the scene's "
      "road_lighting block, with shadows from the scene's objects.");
  road->add_option("scene", args->scene_file, "Scene file (JSON; see docs/road-lighting.md)")->required();
  road->add_option("--set", args->overrides, "Override a scene value: PATH=VALUE (e.g. road_lighting.q0=0.08)");
  road->add_option("--lights", args->lights,
                   "The installation: the lights whose names match this pattern (fnmatch, e.g. 'street lamp*'); "
                   "default all");
  road->add_flag("--json", args->json, "Print JSON (with the grids) instead of a table");
  return [road, args] { return road->parsed() ? run_road(*args) : -1; };
}

}  // namespace skylit::cli
