// `skylit animate` as a user runs it: frames in time order with their labels, one
// exposure for all (each frame remade alone at that exposure gives the same pixels),
// the viewer holding every frame, the MP4 as ffprobe reads it, the statistics, and the
// mistakes, and the viewer in headless Chromium. Images are 32 × 24 (the viewer's 64 × 36)
// at one sample per pixel; 17 renders in all.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "../io/epw_fixture.h"
#include "../io/png_read_util.h"
#include "../test_support.h"
#include "browser_support.h"
#include "skylit/figures/animation_frames.h"
#include "skylit/figures/raster.h"
#include "study_csv.h"

namespace skylit {
namespace {

using testing::csv_rows;
using testing::expect_plot_shows_csv;
using testing::quoted;
using testing::run_skylit;
using testing::TempDir;

// A small scene placed in Munich, its sun set by the time.
std::string sited_scene(const std::string& time, int width = 32, int height = 24) {
  return R"({
  "camera": {"position": [0, -20, 2], "look_at": [0, 0, 3], "vertical_fov_deg": 60},
  "site": {"latitude_deg": 48.14, "longitude_deg": 11.58},
  "time": ")" +
         time + R"(",
  "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
  "objects": [
    {"name": "ground", "type": "plane", "material": "white", "size_m": 200},
    {"name": "box", "type": "box", "material": "white", "center": [0, 0, 3], "size": [4, 4, 6]}
  ],
  "render": {"width": )" +
         std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(, "samples_per_axis": 1}
})";
}

TEST(AnimateCommand, FramesInOrderAtOneExposureWithViewerVideoAndStatistics) {
  TempDir dir;
  const auto scene = dir.write("scene.json", sited_scene("2026-06-21T12:00+02:00"));
  const auto out = dir.path() / "new" / "study";  // made by the command
  const auto r =
      run_skylit("animate " + quoted(scene) +
                 " --from 2026-06-21T07:00+02:00 --to 2026-06-21T19:00+02:00 --every 3h --stats -q -o " + quoted(out));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto rows = csv_rows(testing::read_file(out / "frames.csv"));
  ASSERT_EQ(rows.size(), 6u);  // the header and 07:00, 10:00, ..., 19:00
  EXPECT_EQ(rows[0][7], "exposure_ev");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i][0], std::to_string(i));
    EXPECT_EQ(rows[i][1], "frame_000" + std::to_string(i) + ".png");
    EXPECT_EQ(rows[i][3], (i < 2 ? "0" : "") + std::to_string(4 + 3 * i) + ":00");
    EXPECT_EQ(rows[i][7], rows[1][7]);  // one exposure
    EXPECT_TRUE(std::filesystem::exists(out / rows[i][1]));
  }
  // The sun climbs to noon (13:20 local solar time here) and sinks: a check of the order.
  EXPECT_LT(std::stod(rows[1][5]), std::stod(rows[3][5]));
  EXPECT_GT(std::stod(rows[3][5]), std::stod(rows[5][5]));

  // Frame 3 (13:00) remade alone at the study's exposure: the same pixels above the label.
  const auto alone = dir.path() / "alone.png";
  const auto again = dir.write("at13.json", sited_scene("2026-06-21T13:00+02:00"));
  ASSERT_EQ(
      run_skylit("render " + quoted(again) + " -q --set render.exposure_ev=" + rows[1][7] + " -o " + quoted(alone))
          .exit_status,
      0);
  const Raster frame = test::read_png_raster(out / "frame_0003.png");
  const Raster reference = test::read_png_raster(alone);
  ASSERT_EQ(frame.width, 32);
  ASSERT_EQ(frame.height, 24);
  // The band is the font's line and a pixel above and below it (labelled_frame).
  const std::size_t above_label = 3 * 32 * static_cast<std::size_t>(24 - text_height(1) - 2);
  EXPECT_TRUE(std::equal(reference.rgb.begin(), reference.rgb.begin() + above_label, frame.rgb.begin()));
  EXPECT_NE(frame.rgb, reference.rgb);  // the label is burnt in

  const std::string html = testing::read_file(out / "viewer.html");
  for (int i = 1; i <= 5; ++i) {
    const std::string png = testing::read_file(out / ("frame_000" + std::to_string(i) + ".png"));
    EXPECT_NE(html.find(base64({png.begin(), png.end()})), std::string::npos) << i;
  }
  EXPECT_NE(html.find("max=\"4\""), std::string::npos);

  const auto stats = csv_rows(testing::read_file(out / "statistics.csv"));
  std::size_t box_rows = 0;
  for (const auto& row : stats) box_rows += row.size() > 6 && row[6] == "box" ? 1 : 0;
  EXPECT_EQ(box_rows, 5u);
  expect_plot_shows_csv(stats, out / "statistics.svg", {});

  if (std::system("ffprobe -version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no ffprobe: the MP4 is not checked";
  const std::filesystem::path probe = dir.path() / "probe.txt";
  ASSERT_EQ(std::system(("ffprobe -v error -select_streams v:0 -count_frames -show_entries "
                         "stream=codec_name,pix_fmt,nb_read_frames -of csv=p=0 " +
                         quoted(out / "animation.mp4") + " > " + quoted(probe))
                            .c_str()),
            0);
  EXPECT_EQ(testing::read_file(probe), "h264,yuv420p,5\n");
}

TEST(AnimateCommand, DatesAtNoonAndNoFfmpegStillWritesTheFrames) {
  TempDir dir;
  const auto scene = dir.write("scene.json", sited_scene("2026-06-21T12:00+02:00"));
  // Without ffmpeg on PATH (the program is run by its full path).
  const auto r =
      run_skylit("animate " + quoted(scene) + " --dates 03-21,12-21 --at 12:00 -q -o " + quoted(dir.path() / "d"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const std::string frames = testing::read_file(dir.path() / "d" / "frames.csv");
  EXPECT_NE(frames.find(",2026-12-21,12:00,+01:00,"), std::string::npos) << frames;  // 11.58° E: the +01:00 meridian
  const auto without = testing::run_skylit_with_env(
      "PATH=/nonexistent", "animate " + quoted(scene) + " --dates 06-21 --at 12:00Z -q -o " + quoted(dir.path() / "n"));
  ASSERT_EQ(without.exit_status, 0) << without.output;
  EXPECT_NE(without.output.find("no ffmpeg"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "n" / "frame_0001.png"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "n" / "animation.mp4"));
}

// The viewer as a person uses it, in Debian's headless Chromium: every position of the
// slider, the arrow key and the play button show the frame animate wrote for that
// position (its pixels, read back through a canvas) and its label (date, time and sun
// altitude as in frames.csv), with no script error. Four frames at 64 × 36; about 3 s,
// most of it Chromium's start. Skipped only when no Chromium is installed.
TEST(AnimateCommand, ViewerInChromiumShowsEachFrameWithItsLabel) {
  const std::filesystem::path chromium = testing::find_chromium();
  if (!std::filesystem::exists(chromium))
    GTEST_SKIP() << "no Chromium (" << chromium
                 << " does not exist): the viewer's browser test needs it; scripts/install-deps.sh installs it";
  TempDir dir;
  const auto scene = dir.write("scene.json", sited_scene("2026-03-21T12:00+01:00", 64, 36));
  const auto out = dir.path() / "study";
  const auto r =
      run_skylit("animate " + quoted(scene) +
                 " --from 2026-03-21T09:00+01:00 --to 2026-03-21T18:00+01:00 --every 3h --fps 20 -q -o " + quoted(out));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto rows = csv_rows(testing::read_file(out / "frames.csv"));
  ASSERT_EQ(rows.size(), 5u);  // the header and four frames

  const testing::PageResult page = testing::run_page_script("viewer_frames.mjs", chromium, out / "viewer.html");
  ASSERT_EQ(page.command.exit_status, 0) << page.command.output;
  const nlohmann::json& seen = page.json;
  ASSERT_TRUE(seen.is_object()) << page.command.output;
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"].dump();
  ASSERT_EQ(seen["count"], 4);
  // What the viewer shows for frame i (0-based) is frame_000<i+1>.png, labelled as in
  // frames.csv: "<n>/4  <date> <time><offset>  sun <altitude to 0.1°>°".
  const auto expect_frame = [&](const nlohmann::json& shown, std::size_t i, const std::string& how) {
    SCOPED_TRACE(how + ", frame " + std::to_string(i + 1));
    ASSERT_LT(i, 4u);
    EXPECT_EQ(shown["slider"], i);
    EXPECT_TRUE(shown["complete"].get<bool>());
    const Raster png = test::read_png_raster(out / rows[i + 1][1]);
    ASSERT_EQ(shown["width"], png.width);
    ASSERT_EQ(shown["height"], png.height);
    EXPECT_TRUE(shown["rgb"].get<std::vector<uint8_t>>() == png.rgb);  // the very pixels written
    const std::vector<std::string>& row = rows[i + 1];
    char altitude[32];
    std::snprintf(altitude, sizeof altitude, "%.1f", std::stod(row[5]));
    EXPECT_EQ(shown["label"], row[0] + "/4  " + row[2] + " " + row[3] + row[4] + "  sun " + altitude + "°");
  };
  expect_frame(seen["first"], 0, "opened");
  ASSERT_EQ(seen["bySlider"].size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) expect_frame(seen["bySlider"][i], i, "slider");
  expect_frame(seen["byKey"], 1, "arrow key from the first");
  expect_frame(seen["afterPlay"], seen["afterPlay"]["slider"].get<std::size_t>(), "played and paused");
  EXPECT_NE(seen["afterPlay"]["slider"], 1);  // play moved on from the second frame
  EXPECT_EQ(seen["playText"], "play");        // paused again
  // The frames differ (the sun moves), so showing the right one is a real check.
  EXPECT_NE(seen["bySlider"][0]["rgb"], seen["bySlider"][1]["rgb"]);
}

TEST(AnimateCommand, MistakesExitTwoAndMakeNoFolder) {
  TempDir dir;
  const auto sited = dir.write("sited.json", sited_scene("2026-06-21T12:00+02:00"));
  const auto unsited = dir.write("unsited.json", testing::small_scene_json(16, 12));
  // One hour of a weather file: its clouds and air would stand for every instant.
  dir.write("site.epw", testing::epw_fixture());
  const auto weathered = dir.write("weathered.json", R"({"camera": {"position": [0, -20, 2], "look_at": [0, 0, 3]},
  "weather": {"epw": "site.epw", "hour": "06-21T13:00"},
  "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
  "objects": [{"name": "ground", "type": "plane", "material": "white", "size_m": 200}],
  "render": {"width": 16, "height": 12, "samples_per_axis": 1}})");
  const std::pair<std::string, std::string> cases[] = {
      {quoted(weathered) + " --dates 06-21 --at 12:00", "--vary weather.hour="},
      {quoted(unsited) + " --dates 06-21 --at 12:00", "--site"},
      {quoted(sited) + " --from 2026-06-21T12:00Z --to 2026-06-21T11:00Z", "comes before"},
      {quoted(sited) + " --from 2026-06-21T12:00Z --to 2026-06-21T13:00Z --every 0s", "--every"},
      {quoted(sited) + " --dates 06-31 --at 12:00", "--dates"},
      {quoted(sited) + " --dates 06-21", "--at"},
      {quoted(sited) + " --dates 06-21 --at 12:00 --shard 3/2", "--shard"},
  };
  for (const auto& [arguments, expected] : cases) {
    const auto r = run_skylit("animate " + arguments + " -q -o " + quoted(dir.path() / "out"));
    EXPECT_EQ(r.exit_status, 2) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out")) << arguments;
  }
}

}  // namespace
}  // namespace skylit
