// `skylit sweep` as a user runs it: every combination's image next to the labelled
// sheet, extra cell formats, and for any problem (a malformed --vary, a value that
// breaks one combination's scene, a bad sheet name) exit status 2, one line naming it,
// and no file written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "../io/epw_fixture.h"
#include "../test_support.h"
#include "study_csv.h"

namespace skylit {
namespace {

using testing::quoted;
using testing::run_skylit;
using testing::TempDir;

std::set<std::string> files_in(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

// Width and height from a PNG's IHDR chunk.
std::pair<uint32_t, uint32_t> png_size(const std::filesystem::path& file) {
  const std::string bytes = testing::read_file(file);
  EXPECT_GE(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  const auto be32 = [&](size_t at) {
    uint32_t v = 0;
    for (size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

TEST(SweepCommand, WritesEveryCombinationAndTheSheet) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  std::filesystem::create_directories(dir.path() / "out");
  // The --vary before the scene: each occurrence takes one argument.
  const auto r = run_skylit("sweep --vary sun.altitude_deg=20,50 " + quoted(scene) +
                            " --vary objects.1.material=white,red --set render.samples_per_axis=1 --quiet -o " +
                            quoted(dir.path() / "out" / "sheet.png"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(files_in(dir.path() / "out"),
            (std::set<std::string>{"sheet.png", "sheet_1_20_white.png", "sheet_2_20_red.png", "sheet_3_50_white.png",
                                   "sheet_4_50_red.png"}));
  EXPECT_EQ(png_size(dir.path() / "out" / "sheet_4_50_red.png"), (std::pair<uint32_t, uint32_t>{24, 16}));
  // Two columns of cells with their labels beside a column of row labels.
  const auto [width, height] = png_size(dir.path() / "out" / "sheet.png");
  EXPECT_GT(width, 2u * 24u + 200u);
  EXPECT_GT(height, 2u * 16u + 40u);
  // The cells differ: the sun's altitude and the box's material show.
  EXPECT_NE(testing::read_file(dir.path() / "out" / "sheet_1_20_white.png"),
            testing::read_file(dir.path() / "out" / "sheet_2_20_red.png"));
  EXPECT_NE(testing::read_file(dir.path() / "out" / "sheet_1_20_white.png"),
            testing::read_file(dir.path() / "out" / "sheet_3_50_white.png"));
}

TEST(SweepCommand, OneVaryAndExtraCellFormats) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  const auto r =
      run_skylit("sweep " + quoted(scene) + " --vary 'camera.position=[0,-20,2];[0,-30,2]' --cell-format exr " +
                 "--threads 2 -o " + quoted(dir.path() / "s.png"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"scene.json", "s.png", "s_1_0_-20_2.png", "s_1_0_-20_2.exr",
                                                         "s_2_0_-30_2.png", "s_2_0_-30_2.exr"}));
}

TEST(SweepCommand, ValueThatBreaksOneCombinationExitsTwoAndWritesNothing) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  const auto r =
      run_skylit("sweep " + quoted(scene) + " --vary sun.altitude_deg=40,95 --vary objects.1.material=white,red " +
                 "-o " + quoted(dir.path() / "s.png"));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("combination 3 of 4 (sun.altitude_deg = 95, objects.1.material = white)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("sun.altitude_deg"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"scene.json"}));
}

TEST(SweepCommand, UnknownMaterialInOneCombinationExitsTwo) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  const auto r =
      run_skylit("sweep " + quoted(scene) + " --vary objects.1.material=red,plaid -o " + quoted(dir.path() / "s.png"));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("combination 2 of 2 (objects.1.material = plaid)"), std::string::npos) << r.output;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"scene.json"}));
}

TEST(SweepCommand, MalformedArgumentsExitTwo) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  const std::string base = "sweep " + quoted(scene) + " -o " + quoted(dir.path() / "s.png");
  const auto no_equals = run_skylit(base + " --vary sun.altitude_deg");
  EXPECT_EQ(no_equals.exit_status, 2);
  EXPECT_NE(no_equals.output.find("--vary sun.altitude_deg: expected PATH=V1,V2"), std::string::npos)
      << no_equals.output;
  const auto no_values = run_skylit(base + " --vary sun.altitude_deg=");
  EXPECT_EQ(no_values.exit_status, 2);
  EXPECT_NE(no_values.output.find("no values"), std::string::npos) << no_values.output;
  EXPECT_EQ(run_skylit(base).exit_status, 2);  // no --vary
  EXPECT_EQ(run_skylit(base + " --vary a=1 --vary a=2").exit_status, 2);
  EXPECT_EQ(run_skylit(base + " --vary sun.altitude_deg=4 --cell-format jpg").exit_status, 2);
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"scene.json"}));
}

TEST(SweepCommand, BadSheetPathExitsTwoAndAMissingFolderIsMade) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  const auto jpg =
      run_skylit("sweep " + quoted(scene) + " --vary sun.altitude_deg=4 -o " + quoted(dir.path() / "s.jpg"));
  EXPECT_EQ(jpg.exit_status, 2);
  EXPECT_NE(jpg.output.find("s.jpg"), std::string::npos) << jpg.output;
  // A file where the folder should be is refused; a missing folder is made (issue 20),
  // but only once every combination has loaded.
  dir.write("file", "");
  const auto not_folder =
      run_skylit("sweep " + quoted(scene) + " --vary sun.altitude_deg=4 -o " + quoted(dir.path() / "file" / "s.png"));
  EXPECT_EQ(not_folder.exit_status, 2);
  EXPECT_NE(not_folder.output.find("is not a folder"), std::string::npos) << not_folder.output;
  EXPECT_EQ(
      run_skylit("sweep " + quoted(scene) + " --vary sun.altitude_deg=4,95 -o " + quoted(dir.path() / "no" / "s.png"))
          .exit_status,
      2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "no"));
  const auto made = run_skylit("sweep " + quoted(scene) + " --vary sun.altitude_deg=4 -q -o " +
                               quoted(dir.path() / "no" / "deeper" / "s.png"));
  EXPECT_EQ(made.exit_status, 0) << made.output;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "no" / "deeper" / "s.png"));
}

TEST(SweepCommand, DifferingExposuresExitTwo) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  const auto r =
      run_skylit("sweep " + quoted(scene) + " --vary render.exposure_ev=10,12 -o " + quoted(dir.path() / "s.png"));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("render.exposure_ev differs"), std::string::npos) << r.output;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"scene.json"}));
}

TEST(SweepCommand, Fig7ExampleSweepsAtATinySize) {
  TempDir dir;
  const std::filesystem::path scene = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "fig7.json";
  const auto r = run_skylit("sweep " + quoted(scene) +
                            " --vary sun.altitude_deg=17,60,4 --vary materials.walls=tile,aluminium "
                            "--set render.width=16 --set render.height=9 --set render.samples_per_axis=1 --quiet -o " +
                            quoted(dir.path() / "fig7.png"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(files_in(dir.path()).size(), 7u);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "fig7_6_4_aluminium.png"));
}

// A sweep over hours with --stats: one statistics CSV over every combination, led by its
// instant and grouped by the other varied value, and the plot of each object's mean
// luminance over time per group, whose points are the CSV's. 4 renders at 24 × 16.
TEST(SweepCommand, StatisticsOverHoursGatherIntoOneCsvAndAPlot) {
  TempDir dir;
  std::string text = testing::small_scene_json(24, 16);
  const std::string sun = R"("sun": {"altitude_deg": 40, "azimuth_deg": 135})";
  text.replace(text.find(sun), sun.size(),
               R"("site": {"latitude_deg": 48.2, "longitude_deg": 16.37}, "time": "2026-06-21T12:00+02:00")");
  text.replace(text.find(R"({"type": "box")"), 1, R"({"name": "box", )");
  const auto scene = dir.write("scene.json", text);
  const auto r = run_skylit("sweep " + quoted(scene) +
                            " --vary time=2026-06-21T08:00+02:00,2026-06-21T15:00+02:00"
                            " --vary objects.1.material=white,red --set render.samples_per_axis=1 --stats -q -o " +
                            quoted(dir.path() / "out" / "day.png"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto csv = testing::csv_rows(testing::read_file(dir.path() / "out" / "day_statistics.csv"));
  ASSERT_GT(csv.size(), 1u);
  EXPECT_EQ(csv[0][5], "group");
  std::map<std::string, double> box_mean;  // "<time> <group>"
  for (std::size_t i = 1; i < csv.size(); ++i)
    if (csv[i][6] == "object" && csv[i][7] == "box") box_mean[csv[i][2] + " " + csv[i][5]] = std::stod(csv[i][9]);
  ASSERT_EQ(box_mean.size(), 4u);  // two hours × two materials
  // The white box outshines the red one at both hours (a check that the groups are kept apart).
  EXPECT_GT(box_mean["08:00 objects.1.material = white"], box_mean["08:00 objects.1.material = red"]);
  EXPECT_GT(box_mean["15:00 objects.1.material = white"], box_mean["15:00 objects.1.material = red"]);
  testing::expect_plot_shows_csv(csv, dir.path() / "out" / "day_statistics.svg", 5);
  EXPECT_NE(testing::read_file(dir.path() / "out" / "day_statistics.svg").find("box (objects.1.material = red)"),
            std::string::npos);

  // Without an instant there is nothing to plot against: exit 2 before any output.
  const auto unsited = dir.write("unsited.json", testing::small_scene_json(24, 16));
  const auto no_time = run_skylit("sweep " + quoted(unsited) + " --vary sun.altitude_deg=20,50 --stats -q -o " +
                                  quoted(dir.path() / "none" / "s.png"));
  EXPECT_EQ(no_time.exit_status, 2) << no_time.output;
  EXPECT_NE(no_time.output.find("--stats plots the statistics over time"), std::string::npos) << no_time.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "none"));
}

// A sweep over the hours of a weather file: a typical year's records come from different
// years (here 2001 and 1995), and the statistics place them in one year, in calendar
// order. 2 renders at 16 × 12.
TEST(SweepCommand, StatisticsOverWeatherFileHoursLieInOneYear) {
  TempDir dir;
  testing::EpwRecordFields other_year;
  other_year.year = 1995, other_year.day = 22;
  dir.write("site.epw", testing::epw_fixture({other_year}));
  const auto scene = dir.write("scene.json", R"({
  "camera": {"position": [0, -20, 2], "look_at": [0, 0, 3]},
  "weather": {"epw": "site.epw", "hour": "06-21T13:00"},
  "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
  "objects": [{"name": "ground", "type": "plane", "material": "white", "size_m": 200}],
  "render": {"width": 16, "height": 12, "samples_per_axis": 1}
})");
  const auto r = run_skylit("sweep " + quoted(scene) + " --vary weather.hour=06-22T13:00,06-21T13:00 --stats -q -o " +
                            quoted(dir.path() / "year.png"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto csv = testing::csv_rows(testing::read_file(dir.path() / "year_statistics.csv"));
  std::set<std::string> dates;
  for (std::size_t i = 1; i < csv.size(); ++i) dates.insert(csv[i][1] + "T" + csv[i][2] + csv[i][3]);
  // The sun at each hour's middle, 12:30 at the fixture's UTC−3:30.
  EXPECT_EQ(dates, (std::set<std::string>{"2000-06-21T12:30-03:30", "2000-06-22T12:30-03:30"}));
  testing::expect_plot_shows_csv(csv, dir.path() / "year_statistics.svg", std::nullopt);
}

TEST(SweepCommand, HelpExitsZero) {
  const auto help = run_skylit("sweep --help");
  EXPECT_EQ(help.exit_status, 0);
  EXPECT_NE(help.output.find("--vary"), std::string::npos) << help.output;
}

}  // namespace
}  // namespace skylit
