// `skylit sweep`: renders a scene for every combination of `--vary` values, writes each
// image next to the contact sheet and the sheet itself, labelled (docs/sweeps.md).
// Every combination's scene is loaded before anything is rendered, so a bad value in
// any of them costs nothing and leaves no file behind.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "job_split.h"
#include "process_group.h"
#include "progress_bar.h"
#include "skylit/assess/render_statistics.h"
#include "skylit/core/error.h"
#include "skylit/core/file_names.h"
#include "skylit/figures/contact_sheet.h"
#include "skylit/figures/study_statistics.h"
#include "skylit/figures/sweep.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/pixel_layers.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/render/renderer.h"
#include "skylit/sun/time_steps.h"

namespace skylit::cli {

namespace {

struct SweepArguments {
  std::string scene_file;
  std::string sheet;
  std::vector<std::string> varies;
  std::vector<std::string> overrides;
  std::vector<std::string> cell_formats;  // besides png
  std::string title;
  bool statistics = false;
  int threads = 0;
  bool quiet = false;
  std::string shard;
  JobSplit split;
};

void check_sheet_path(const std::filesystem::path& sheet) {
  if (lower_case_extension(sheet) != ".png")
    throw InputError("cannot write \"" + sheet.string() + "\": a contact sheet is written as .png");
  // The sheet's folder is made when missing (after every check), as for animate.
  const std::filesystem::path folder = sheet.parent_path();
  if (!folder.empty() && std::filesystem::exists(folder) && !std::filesystem::is_directory(folder))
    throw InputError("cannot write \"" + sheet.string() + "\": \"" + folder.string() + "\" is not a folder");
}

std::vector<std::string> with_overrides(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

// Loads every combination's scene (--set first, then the combination's values) and
// returns the one exposure they share: InputError naming the combination otherwise.
std::optional<double> check_combinations(const SweepArguments& args, const SweepPlan& plan) {
  std::optional<std::optional<double>> shared;
  for (const SweepCombination& combination : plan.combinations) {
    const std::string name = "combination " + std::to_string(combination.index + 1) + " of " +
                             std::to_string(plan.combinations.size()) + " (" + combination_label(plan, combination) +
                             ")";
    try {
      const Scene scene =
          load_scene(args.scene_file, with_overrides(args.overrides, sweep_overrides(plan, combination)));
      if (!shared) shared = scene.render.exposure_ev;
      if (*shared != scene.render.exposure_ev)
        throw InputError("render.exposure_ev differs between combinations; the sheet and its cells share one exposure");
    } catch (const InputError& e) {
      throw InputError(name + ": " + e.what());
    }
  }
  return *shared;
}

constexpr int kTypicalYear = 2000;

// The varied paths that set the instant: a sweep over them is a sweep over time.
bool sets_the_time(const std::string& path) { return path == "time" || path == "weather.hour"; }

// --stats: each combination as a frame at its scene's instant (the `time`, or the one
// weather.hour sets), grouped by its values other than the time; InputError if a
// combination's scene has no instant.
struct SweepFrames {
  std::vector<AnimationFrame> frames;
  std::vector<std::string> groups;
};

SweepFrames sweep_frames(const SweepArguments& args, const SweepPlan& plan) {
  SweepFrames out;
  for (const SweepCombination& combination : plan.combinations) {
    const Scene scene = load_scene(args.scene_file, with_overrides(args.overrides, sweep_overrides(plan, combination)));
    const std::string label = combination_label(plan, combination);
    if (scene.time.empty())
      throw InputError("sweep --stats plots the statistics over time, and combination " +
                       std::to_string(combination.index + 1) + " (" + label +
                       ") has none: give the scene a 'time' and a 'site', or vary time or weather.hour");
    OffsetDateTime time = parse_offset_date_time(scene.time, args.scene_file + ": time");
    // A typical year's months come from different years: its hours are placed in one
    // year, 2000 (a leap year, so that February 29 exists), to lie in calendar order.
    if (scene.weather) time.year = kTypicalYear;
    out.frames.push_back(
        {static_cast<int>(combination.index) + 1, time, scene.sun.altitude_deg, scene.sun.azimuth_deg});
    std::string group;
    for (std::size_t p = 0; p < plan.parameters.size(); ++p)
      if (!sets_the_time(plan.parameters[p].path))
        group += (group.empty() ? "" : " / ") + plan.parameters[p].path + " = " + combination.values[p];
    out.groups.push_back(group);
  }
  // A sweep over the time alone has no groups (and its CSV no group column).
  if (std::all_of(out.groups.begin(), out.groups.end(), [](const std::string& g) { return g.empty(); }))
    out.groups.clear();
  return out;
}

// NAME_statistics.csv and NAME_statistics.svg beside the sheet NAME.png.
std::filesystem::path beside_sheet(const std::filesystem::path& sheet, const std::string& suffix) {
  return sheet.parent_path() / (sheet.stem().string() + suffix);
}

int run_sweep(SweepArguments& args) {
  if (!args.shard.empty()) args.split.shard = parse_shard(args.shard);
  check_split_options(args.split);
  const std::filesystem::path sheet_path = args.sheet;
  check_sheet_path(sheet_path);
  check_not_an_input(sheet_path, args.scene_file);
  std::vector<SweepParameter> parameters;
  for (const std::string& vary : args.varies) parameters.push_back(parse_sweep_parameter(vary));
  const SweepPlan plan = plan_sweep(std::move(parameters));
  std::vector<std::string> extensions = {".png"};
  for (const std::string& format : args.cell_formats)
    if (std::find(extensions.begin(), extensions.end(), "." + format) == extensions.end())
      extensions.push_back("." + format);
  const std::optional<double> fixed_exposure = check_combinations(args, plan);
  const SweepFrames frames = args.statistics ? sweep_frames(args, plan) : SweepFrames{};
  if (!sheet_path.parent_path().empty()) std::filesystem::create_directories(sheet_path.parent_path());

  const bool show_progress = !args.quiet && is_first_process() && isatty(STDERR_FILENO) != 0;
  const auto render_cell = [&](std::size_t index) {
    const SweepCombination& combination = plan.combinations[index];
    if (show_progress)
      std::fprintf(stderr, "cell %zu/%zu: %s\n", combination.index + 1, plan.combinations.size(),
                   combination_label(plan, combination).c_str());
    const Scene scene = load_scene(args.scene_file, with_overrides(args.overrides, sweep_overrides(plan, combination)));
    const Renderer renderer(scene);
    ProgressBar progress(show_progress);
    RenderOptions options;
    options.threads = args.threads;
    options.on_progress = [&progress](int done, int total) { progress.update(done, total); };
    return renderer.render(options);
  };
  const auto shard_file = [&](std::size_t index) {
    return sweep_cell_path(sheet_path, plan, plan.combinations[index], ".xyz");
  };
  const std::optional<std::vector<XyzImage>> images =
      gather_job_images(plan.combinations.size(), args.split, render_cell, shard_file);
  if (!images) return 0;  // a shard, or a rank other than the first

  ContactSheet sheet;
  sheet.title = args.title.empty() ? std::filesystem::path(args.scene_file).filename().string() : args.title;
  sheet.row_labels = plan.row_labels;
  sheet.column_labels = plan.column_labels;
  sheet.cells.assign(plan.rows, std::vector<const XyzImage*>(plan.columns, nullptr));
  for (const SweepCombination& combination : plan.combinations)
    sheet.cells[combination.row][combination.column] = &(*images)[combination.index];
  sheet.display.exposure_ev = fixed_exposure;
  // The cell PNGs use the sheet's exposure, so that they compare as the sheet does.
  const DisplayOptions display{contact_sheet_exposure_ev(sheet)};
  for (const SweepCombination& combination : plan.combinations)
    for (const std::string& extension : extensions)
      write_image((*images)[combination.index], sweep_cell_path(sheet_path, plan, combination, extension), display);
  write_contact_sheet(sheet, sheet_path);

  if (args.statistics) {
    // The objects each pixel sees change only with the values other than the time: one
    // tracing of the camera's rays per group serves its combinations.
    std::map<std::string, PixelLayers> layers_of_group;
    std::vector<RenderStatistics> statistics;
    for (const SweepCombination& combination : plan.combinations) {
      const Scene scene =
          load_scene(args.scene_file, with_overrides(args.overrides, sweep_overrides(plan, combination)));
      const std::string group = frames.groups.empty() ? "" : frames.groups[combination.index];
      auto layers = layers_of_group.find(group);
      if (layers == layers_of_group.end())
        layers = layers_of_group.emplace(group, trace_pixel_layers(PreparedScene(scene))).first;
      statistics.push_back(render_statistics((*images)[combination.index], layers->second, scene));
    }
    AtomicFile(beside_sheet(sheet_path, "_statistics.csv"))
        .commit(study_statistics_csv(frames.frames, statistics, frames.groups));
    write_plot(study_statistics_plot(sheet.title, frames.frames, statistics, frames.groups),
               beside_sheet(sheet_path, "_statistics.svg"));
  }
  return 0;
}

}  // namespace

CommandRunner add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArguments>();
  CLI::App* sweep =
      app.add_subcommand("sweep",
                         "Render a scene for every combination of --vary values: one image per combination, next to a "
                         "labelled contact sheet.");
  sweep->add_option("scene", args->scene_file, "Scene file (JSON; see docs/scene-format.md)")->required();
  sweep
      ->add_option("-o,--output", args->sheet,
                   "The contact sheet, .png; each combination's image is written next to it as "
                   "NAME_<n>_<values>.<format>. Its folder is made when missing")
      ->required();
  sweep
      ->add_option("--vary", args->varies,
                   "PATH=V1,V2,...: values of one scene value (as --set). Repeat it: every combination is rendered; "
                   "the last --vary gives the columns, the ones before it the rows. Values are numbers or words "
                   "separated by ','; separate them by ';' when they hold commas ([0,1,2];[3,4,5])")
      ->required()
      ->allow_extra_args(false);
  sweep
      ->add_option("--set", args->overrides,
                   "Override a scene value for every combination: PATH=VALUE, e.g. --set render.width=640")
      ->allow_extra_args(false);
  sweep
      ->add_option("--cell-format", args->cell_formats,
                   "Also write each combination's image as exr, pfm or hdr (absolute, linear); repeat for "
                   "several. The PNGs are always written")
      ->allow_extra_args(false)
      ->check(CLI::IsMember({"exr", "pfm", "hdr"}));
  sweep->add_option("--title", args->title, "The sheet's title (default: the scene file's name)");
  sweep->add_flag("--stats", args->statistics,
                  "Also write NAME_statistics.csv (every combination's luminance statistics, by its instant) and "
                  "NAME_statistics.svg (mean luminance of each object and the sky over time); for sweeps over "
                  "time or weather.hour");
  sweep->add_option("--threads", args->threads, "Worker threads (0: all cores); the images do not depend on it")
      ->check(CLI::Range(0, 1024));
  sweep->add_flag("-q,--quiet", args->quiet, "No progress lines");
  add_split_options(*sweep, args->shard, args->split, "combinations", "NAME_<n>_<values>.xyz next to the sheet");
  return [sweep, args] { return sweep->parsed() ? run_sweep(*args) : -1; };
}

}  // namespace skylit::cli
