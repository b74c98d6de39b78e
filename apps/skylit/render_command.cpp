// `skylit render`: a scene file into one or more images.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "process_group.h"
#include "progress_bar.h"
#include "render_outputs.h"
#include "skylit/core/error.h"
#include "skylit/io/image/image.h"
#include "skylit/io/output_files.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_report.h"
#include "skylit/render/renderer.h"
#include "skylit/render/surface_illuminance.h"

namespace skylit::cli {

namespace {

struct RenderArguments {
  std::string scene_file;
  std::vector<std::string> outputs;
  std::vector<std::string> reports;  // --report: outputs too, named apart for the help
  std::vector<std::string> standard_error_outputs;
  std::vector<std::string> overrides;
  std::string hour;  // --hour: weather.hour
  int threads = 0;
  bool quiet = false;
  bool verbose = false;
  bool preview = false;
  bool make_folders = false;
};

// A quarter of the pixels and the cheapest sampling, for framing and iterating.
void make_preview(RenderSettings& render) {
  render.width = std::max(1, render.width / 2);
  render.height = std::max(1, render.height / 2);
  render.samples_per_axis = 1;
  render.samples_per_pixel = std::min(render.samples_per_pixel, 4);
}

int run_render(RenderArguments args) {
  args.outputs.insert(args.outputs.end(), args.reports.begin(), args.reports.end());
  // Every output's format, folder and name checked, and its temporary file made, before
  // the work, so that a typo costs nothing; written all or nothing after it.
  std::vector<std::filesystem::path> all_outputs(args.outputs.begin(), args.outputs.end());
  all_outputs.insert(all_outputs.end(), args.standard_error_outputs.begin(), args.standard_error_outputs.end());
  for (const std::filesystem::path& out : all_outputs) check_render_output(out.string());
  std::optional<OutputFiles> outputs;
  if (!args.make_folders) outputs.emplace(all_outputs, std::vector<std::filesystem::path>{args.scene_file});
  std::vector<std::string> overrides = args.overrides;
  if (!args.hour.empty()) overrides.push_back("weather.hour=" + args.hour);
  Scene scene = load_scene(args.scene_file, overrides);
  if (args.make_folders) {  // only once the scene has loaded: a mistake leaves no folder behind
    for (const std::filesystem::path& out : all_outputs)
      if (!out.parent_path().empty()) std::filesystem::create_directories(out.parent_path());
    outputs.emplace(all_outputs, std::vector<std::filesystem::path>{args.scene_file});
  }
  if (args.preview) make_preview(scene.render);
  // Likely mistakes are said before the work; the camera checks build a ray-tracing
  // structure of their own, so only when asked for.
  if (args.verbose) std::fputs((describe_objects(scene) + describe_lights(scene)).c_str(), stderr);
  print_scene_warnings(scene, /*check_camera=*/args.verbose);
  if (!args.standard_error_outputs.empty() && scene.render.integrator != Integrator::path)
    throw InputError(args.scene_file +
                     ": --standard-error needs render.integrator \"path\" (the bands method has no noise)");
  const Renderer renderer(scene);
  ProgressBar progress(!args.quiet && is_first_process() && isatty(STDERR_FILENO) != 0);
  RenderOptions options;
  options.threads = args.threads;
  options.on_progress = [&progress](int done, int total) { progress.update(done, total); };
  // Under mpirun the ranks share the image's tiles; the first writes the outputs.
  options.share = image_share_of_processes();
  FrameBreakdown breakdown;
  const bool bands = scene.render.integrator != Integrator::path;
  if (args.verbose && bands) options.breakdown = &breakdown;
  const Renderer::Result result = renderer.render_with_error(options);
  if (!is_first_process()) return 0;
  if (options.breakdown) std::fprintf(stderr, "%s\n", describe(breakdown).c_str());
  DisplayOptions display;
  display.exposure_ev = scene.render.exposure_ev;
  display.human = scene.render.human_display;
  display.degrees_per_pixel = scene.camera.vertical_fov_deg / scene.render.height;
  std::optional<PixelLayers> layers;
  if (outputs_need_layers(args.outputs, scene)) {
    layers = trace_pixel_layers(renderer.prepared());
    SurfaceIlluminance lux = surface_illuminance(renderer.prepared(), renderer.bands());
    layers->illuminance_lx = std::move(lux.total_lx);
    layers->reflected_sun_lx = std::move(lux.reflected_sun_lx);
  }
  std::size_t next = 0;
  for (const std::string& out : args.outputs)
    outputs->write(
        next++, render_output_bytes(out, result.image, scene, display, layers ? &*layers : nullptr, args.scene_file));
  for (const std::string& out : args.standard_error_outputs)
    outputs->write(next++, encode_image(*result.standard_error, out, display));
  outputs->publish();
  return 0;
}

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArguments>();
  CLI::App* render = app.add_subcommand("render", "Render a scene file into one or more images.");
  render->add_option("scene", args->scene_file, "Scene file (JSON; see docs/scene-format.md)")->required();
  render->add_option("-o,--output", args->outputs,
                     "Output image; repeat for several. By extension: .exr and .pfm hold linear RGB "
                     "(sRGB primaries) scaled so 0.2126R+0.7152G+0.0722B is luminance in cd/m² "
                     "(EXR adds a Y channel in cd/m²); .hdr is Radiance RGBE (luminance = 179 × "
                     "(0.265R+0.670G+0.065B) cd/m²); .png is a tone-mapped display image; *.falsecolor.png "
                     "is luminance in false colour with a legend (render.false_colour); .json or .csv are "
                     "luminance statistics per object, material and probe, and DGP for a 180° fisheye; .html is "
                     "the report (as --report)");
  render->add_option("--report", args->reports,
                     "Also write a self-contained HTML report: the images and their false colour, the conditions, "
                     "the statistics, and the luminance in cd/m² under the mouse (docs/report.md)");
  render->add_option("--standard-error", args->standard_error_outputs,
                     "With render.integrator \"path\": also write each pixel's standard error of the mean "
                     "(luminance in cd/m², as a grey) to this image; repeat for several formats");
  render->add_option("--set", args->overrides,
                     "Override a scene value: PATH=VALUE, e.g. --set sun.altitude_deg=4 "
                     "--set render.width=640 (degrees, metres and pixels as in the scene file)");
  render->add_option("--hour", args->hour,
                     "The weather file's hour to render, MM-DDThh:mm in the file's standard time (as weather.hour; "
                     "docs/weather.md)");
  render->add_option("--threads", args->threads, "Worker threads (0: all cores); the image does not depend on it")
      ->check(CLI::Range(0, 1024));
  render->add_flag("-q,--quiet", args->quiet, "No progress bar");
  render->add_flag("--mkdir", args->make_folders, "Make the outputs' folders when missing (otherwise an error)");
  render->add_flag("--preview", args->preview,
                   "Half the width and height (a quarter of the pixels), 1×1 samples per pixel (path: at most 4): "
                   "for framing and iteration");
  render->add_flag("-v,--verbose", args->verbose,
                   "Say what the scene loads (as skylit info), check the camera for likely mistakes, and after the "
                   "render say where the frame's time went, on stderr");
  return [render, args] {
    if (!render->parsed()) return -1;
    if (args->outputs.empty() && args->reports.empty())
      throw InputError("render: give an output: -o FILE or --report FILE");
    return run_render(*args);
  };
}

}  // namespace skylit::cli
