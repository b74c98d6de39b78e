// `skylit animate`: a sun study. One scene rendered at a series of instants (a range at
// a fixed step, or one clock time on several dates) with the sun placed for each by the
// solar position algorithm, all frames at one exposure, labelled; then a CSV of the
// labels, an HTML viewer with a time slider, an MP4 when ffmpeg is installed, and on
// request every frame's statistics and their plot over time (docs/animations.md).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "job_split.h"
#include "number_checks.h"
#include "process_group.h"
#include "progress_bar.h"
#include "skylit/assess/render_statistics.h"
#include "skylit/core/error.h"
#include "skylit/figures/animation_frames.h"
#include "skylit/figures/contact_sheet.h"
#include "skylit/figures/study_statistics.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image.h"
#include "skylit/io/image/image_encoders.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/pixel_layers.h"
#include "skylit/render/renderer.h"
#include "skylit/sun/solar_position.h"
#include "skylit/sun/time_steps.h"
#include "video_encoder.h"

namespace skylit::cli {

namespace {

struct AnimateArguments {
  std::string scene_file;
  std::string output_folder;
  std::string from, to, every = "1h";
  std::string dates, at;
  int year = 2026;
  std::vector<double> site;  // latitude, longitude
  std::vector<std::string> overrides;
  std::vector<std::string> frame_formats;  // besides png
  double frames_per_second = 4;
  bool statistics = false;
  std::string title;
  int threads = 0;
  bool quiet = false;
  std::string shard;
  JobSplit split;
};

// The instants the arguments ask for: --from/--to/--every, or --dates/--at.
std::vector<OffsetDateTime> study_instants(const AnimateArguments& args, const SiteLocation& site) {
  const bool range = !args.from.empty() || !args.to.empty();
  const bool dates = !args.dates.empty() || !args.at.empty();
  if (range == dates) throw InputError("animate: give either --from and --to (with --every), or --dates and --at");
  if (range) {
    if (args.from.empty() || args.to.empty()) throw InputError("animate: --from and --to go together");
    return instants_every(parse_offset_date_time(args.from, "--from"), parse_offset_date_time(args.to, "--to"),
                          parse_step_seconds(args.every, "--every"), "--from/--to");
  }
  if (args.dates.empty() || args.at.empty()) throw InputError("animate: --dates and --at go together");
  // A clock time without an offset is read on the site's standard meridian (15° per hour).
  const int standard_offset_minutes = 60 * static_cast<int>(std::lround(site.longitude_deg / 15.0));
  return instants_on_dates(args.dates, args.year, parse_clock_time(args.at, standard_offset_minutes, "--at"),
                           "--dates");
}

// Frame numbers are zero-padded to at least four digits, so that names sort.
int frame_digits(std::size_t count) { return std::max<int>(4, static_cast<int>(std::to_string(count).size())); }

std::string frame_name(std::size_t number, std::size_t count, const std::string& extension) {
  std::string digits = std::to_string(number);
  digits.insert(0, static_cast<std::size_t>(std::max(0, frame_digits(count) - static_cast<int>(digits.size()))), '0');
  return "frame_" + digits + extension;
}

// Places the sun for the frame's instant, as the scene's `time` would.
void place_sun(Scene& scene, const SolarPosition& sun) {
  scene.sun.altitude_deg = sun.altitude_deg;
  scene.sun.azimuth_deg = sun.azimuth_deg;
  scene.atmosphere.earth_sun_distance_au = sun.earth_sun_distance_au;
}

int run_animate(AnimateArguments& args) {
  if (!args.shard.empty()) args.split.shard = parse_shard(args.shard);
  check_split_options(args.split);
  const std::filesystem::path folder = args.output_folder;
  if (std::filesystem::exists(folder) && !std::filesystem::is_directory(folder))
    throw InputError("cannot write the animation into \"" + folder.string() + "\": it is not a folder");
  Scene scene = load_scene(args.scene_file, args.overrides);
  if (!args.site.empty()) scene.site = SiteLocation{args.site[0], args.site[1], scene.atmosphere.site_elevation_m};
  if (!scene.site)
    throw InputError(args.scene_file +
                     ": animate places the sun from the site: give the scene a 'site' "
                     "(latitude_deg, longitude_deg) or --site LAT,LON");
  // Each frame places the sun; the moon (docs/night-sky.md) does not follow it yet.
  if (scene.atmosphere.moon)
    throw InputError(args.scene_file +
                     ": animate places the sun for each frame and does not move the moon: give "
                     "the scene \"moon\": false");
  // A weather file's hour sets the air, the sky, the clouds and the fog of that hour; a
  // study moving only the sun would show every instant under them.
  if (scene.weather)
    throw InputError(args.scene_file +
                     ": the scene takes its conditions from one hour of a weather file, which animate would keep "
                     "for every frame while it moves the sun: render the file's hours with skylit sweep "
                     "--vary weather.hour=MM-DDThh:mm,... (--stats plots them), or give the scene a 'time' instead");
  const std::vector<OffsetDateTime> instants = study_instants(args, *scene.site);
  std::vector<AnimationFrame> frames;
  std::vector<SolarPosition> suns;
  for (const OffsetDateTime& t : instants) {
    if (t.year < kSolarPositionFirstYear || t.year > kSolarPositionLastYear)
      throw InputError("animate: " + format_offset_date_time(t) +
                       " is outside the years the solar position "
                       "algorithm covers");
    suns.push_back(solar_position(*scene.site, t));
    frames.push_back({static_cast<int>(frames.size()) + 1, t, suns.back().altitude_deg, suns.back().azimuth_deg});
  }
  std::filesystem::create_directories(folder);  // every input checked: now the folder may be made

  const bool show_progress = !args.quiet && is_first_process() && isatty(STDERR_FILENO) != 0;
  const auto render_frame = [&](std::size_t i) {
    if (show_progress) std::fprintf(stderr, "frame %s\n", frame_label(frames[i], frames.size()).c_str());
    place_sun(scene, suns[i]);
    const Renderer renderer(scene);
    ProgressBar progress(show_progress);
    RenderOptions options;
    options.threads = args.threads;
    options.on_progress = [&progress](int done, int total) { progress.update(done, total); };
    return renderer.render(options);
  };
  const auto shard_file = [&](std::size_t i) { return folder / frame_name(i + 1, frames.size(), ".xyz"); };
  const std::optional<std::vector<XyzImage>> images =
      gather_job_images(frames.size(), args.split, render_frame, shard_file);
  if (!images) return 0;  // a shard, or a rank other than the first

  // One exposure for the whole study (the contact sheet's meter over every frame), so
  // that the day's brightening and dimming shows.
  ContactSheet all_frames;
  all_frames.cells.emplace_back();
  for (const XyzImage& image : *images) all_frames.cells.back().push_back(&image);
  all_frames.display.exposure_ev = scene.render.exposure_ev;
  DisplayOptions display;
  display.exposure_ev = contact_sheet_exposure_ev(all_frames);

  std::vector<std::string> labels, png_names;
  std::vector<std::vector<uint8_t>> pngs;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    check_pixels_finite((*images)[i], folder / frame_name(i + 1, frames.size(), ".png"));
    labels.push_back(frame_label(frames[i], frames.size()));
    const Raster labelled = labelled_frame((*images)[i], display, labels.back());
    pngs.push_back(encode_png_rgb8(labelled.width, labelled.height, labelled.rgb));
    png_names.push_back(frame_name(i + 1, frames.size(), ".png"));
    AtomicFile(folder / png_names.back()).commit(pngs.back());
    for (const std::string& format : args.frame_formats)
      write_image((*images)[i], folder / frame_name(i + 1, frames.size(), "." + format), display);
  }
  AtomicFile(folder / "frames.csv").commit(frames_csv(frames, png_names, *display.exposure_ev));
  const std::string title =
      args.title.empty() ? std::filesystem::path(args.scene_file).filename().string() : args.title;
  AtomicFile(folder / "viewer.html").commit(frame_viewer_html(title, labels, pngs, args.frames_per_second));

  if (args.statistics) {
    // The objects each pixel sees do not change with the sun: one tracing serves all frames.
    place_sun(scene, suns[0]);
    const Renderer renderer(scene);
    const PixelLayers layers = trace_pixel_layers(renderer.prepared());
    std::vector<RenderStatistics> statistics;
    for (const XyzImage& image : *images) statistics.push_back(render_statistics(image, layers, scene));
    AtomicFile(folder / "statistics.csv").commit(study_statistics_csv(frames, statistics));
    write_plot(study_statistics_plot(title, frames, statistics), folder / "statistics.svg");
  }

  if (const std::optional<std::filesystem::path> ffmpeg = find_ffmpeg()) {
    const std::string pattern = "frame_%0" + std::to_string(frame_digits(frames.size())) + "d.png";
    const std::string failure =
        encode_video(*ffmpeg, folder / pattern, args.frames_per_second, folder / "animation.mp4");
    if (!failure.empty()) throw std::runtime_error("animation.mp4: " + failure);
  } else {
    std::fprintf(stderr,
                 "skylit: no ffmpeg on PATH, so no animation.mp4 (the frames, viewer.html and frames.csv are "
                 "written); install it (Debian: apt-get install ffmpeg) and run again for the video\n");
  }
  return 0;
}

}  // namespace

CommandRunner add_animate_command(CLI::App& app) {
  auto args = std::make_shared<AnimateArguments>();
  CLI::App* animate = app.add_subcommand(
      "animate",
      "A sun study: the scene at a series of instants with the sun placed by the site and the time, one exposure "
      "for all frames, labelled frames, a viewer and a video (docs/animations.md).");
  animate->add_option("scene", args->scene_file, "Scene file (JSON; see docs/scene-format.md)")->required();
  animate
      ->add_option("-o,--output", args->output_folder,
                   "Folder for frame_NNNN.png, frames.csv, viewer.html and animation.mp4; made when missing")
      ->required();
  animate->add_option("--from", args->from, "First instant, ISO 8601 with its UTC offset, e.g. 2026-06-21T05:00+02:00");
  animate->add_option("--to", args->to, "Last instant (included when the step reaches it)");
  animate->add_option("--every", args->every, "Step between frames: 10min, 30s, 1h, 1d (default 1h)");
  animate->add_option("--dates", args->dates, "Dates MM-DD or YYYY-MM-DD separated by commas, e.g. 03-21,06-21");
  animate->add_option("--at", args->at,
                      "Clock time on each of --dates, hh:mm with an optional UTC offset (default: the site's "
                      "standard meridian, 15° of longitude per hour)");
  animate->add_option("--year", args->year, "Year of MM-DD dates (default 2026)")->check(CLI::Range(1, 9999));
  animate
      ->add_option("--site", args->site,
                   "LAT,LON in degrees (north and east positive), when the scene has no site or for another one")
      ->delimiter(',')
      ->expected(2)
      ->check(finite_range(-180, 180));
  animate->add_option("--set", args->overrides, "Override a scene value: PATH=VALUE")->allow_extra_args(false);
  animate
      ->add_option("--frame-format", args->frame_formats,
                   "Also write each frame as exr, pfm or hdr (absolute, linear, no label); repeat for several")
      ->allow_extra_args(false)
      ->check(CLI::IsMember({"exr", "pfm", "hdr"}));
  animate->add_option("--fps", args->frames_per_second, "Frames per second of the video and the viewer (default 4)")
      ->check(finite_range(0.1, 120));
  animate->add_flag("--stats", args->statistics,
                    "Also write statistics.csv (every frame's luminance statistics) and statistics.svg (mean "
                    "luminance of each object and the sky over time)");
  animate->add_option("--title", args->title, "Title of the viewer and the plot (default: the scene file's name)");
  animate->add_option("--threads", args->threads, "Worker threads (0: all cores); the images do not depend on it")
      ->check(CLI::Range(0, 1024));
  animate->add_flag("-q,--quiet", args->quiet, "No progress lines");
  add_split_options(*animate, args->shard, args->split, "frames", "frame_NNNN.xyz in the folder");
  return [animate, args] { return animate->parsed() ? run_animate(*args) : -1; };
}

}  // namespace skylit::cli
