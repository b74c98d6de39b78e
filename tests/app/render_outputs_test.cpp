// `skylit render` with the assessment outputs: a 180° fisheye view gives statistics with
// its DGP, a .hdr with its VIEW= line, EXR data layers with the object table, and a
// false-colour PNG; a wrong output name fails before the work and leaves nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "../test_support.h"
#include "skylit/io/image/image_reader.h"

namespace skylit {
namespace {

using testing::quoted;
using testing::read_file;
using testing::run_skylit;
using testing::TempDir;

TEST(RenderOutputs, FisheyeStatisticsViewLineLayersAndFalseColour) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(40, 40));
  const std::string set =
      " --set camera.projection=fisheye_equidistant --set camera.vertical_fov_deg=180"
      " --set render.exr_layers=true --set 'probes=[{\"name\": \"centre\", \"pixel\": [20, 20]}]'";
  const auto r = run_skylit("render " + quoted(scene) + set + " --quiet -o " + quoted(dir.path() / "v.exr") + " -o " +
                            quoted(dir.path() / "v.hdr") + " -o " + quoted(dir.path() / "s.json") + " -o " +
                            quoted(dir.path() / "s.csv") + " -o " + quoted(dir.path() / "v.falsecolor.png"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const std::string json = read_file(dir.path() / "s.json");
  EXPECT_NE(json.find("\"glare\": {\"dgp\": "), std::string::npos) << json;
  EXPECT_NE(json.find("{\"name\": \"centre\""), std::string::npos) << json;
  EXPECT_NE(read_file(dir.path() / "s.csv").find("\nglare,dgp,,"), std::string::npos);
  EXPECT_NE(read_file(dir.path() / "v.hdr").find("\nVIEW= -vta -vp 0 -20 2 "), std::string::npos);
  const std::string exr = read_file(dir.path() / "v.exr");
  EXPECT_NE(json.find("\"illuminance_lx\": {\"pixels\": "), std::string::npos) << json;
  for (const char* name : {"object", "distance", "normal.X", "illuminance", "skylit:objects"})
    EXPECT_NE(exr.find(name), std::string::npos) << name;
  EXPECT_NE(exr.find("0 objects[0]\n1 objects[1]\n"), std::string::npos);  // unnamed: their place in the file
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "v.falsecolor.png"));
  // The image itself is still read as before: the extra channels do not disturb it.
  EXPECT_EQ(read_image(dir.path() / "v.exr").width, 40);
}

// An illuminance false-colour image needs the layers: they are made for it alone.
TEST(RenderOutputs, IlluminanceFalseColour) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(24, 16));
  const auto r = run_skylit("render " + quoted(scene) + " --quiet --set render.false_colour.quantity=illuminance -o " +
                            quoted(dir.path() / "lux.falsecolor.png"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "lux.falsecolor.png"));
}

TEST(RenderOutputs, WrongNameFailsBeforeTheWork) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(8, 8));
  const auto r = run_skylit("render " + quoted(scene) + " -o " + quoted(dir.path() / "s.txt"));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("s.txt"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path() / "") || !std::filesystem::exists(dir.path() / "s.txt"));
}

}  // namespace
}  // namespace skylit
