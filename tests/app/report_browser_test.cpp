// The HTML report in a real browser (docs/report.md): `skylit render --report` writes a
// page that Debian's headless Chromium, driven by playwright-core
// (tests/browser/run-in-chromium.sh installs it with npm ci), opens; every image must
// load and the read-out with the mouse over a known pixel must show the luminance the
// EXR of the same render holds. Skipped only when no Chromium is installed.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../test_support.h"
#include "browser_support.h"
#include "skylit/figures/report_luminance.h"
#include "skylit/io/image/image_reader.h"

namespace skylit {
namespace {

using testing::find_chromium;
using testing::quoted;
using testing::read_file;
using testing::run_skylit;
using testing::TempDir;

// The EXR's illuminance layer (render.exr_layers), read through OpenEXR.
std::vector<float> exr_illuminance(const std::filesystem::path& path) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  std::vector<float> lux(std::size_t(window.max.x - window.min.x + 1) * (window.max.y - window.min.y + 1), NAN);
  Imf::FrameBuffer frame;
  frame.insert("illuminance", Imf::Slice::Make(Imf::FLOAT, lux.data(), window));
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  return lux;
}

TEST(ReportInBrowser, ImagesLoadAndReadOutShowsTheExrLuminance) {
  const std::filesystem::path chromium = find_chromium();
  if (!std::filesystem::exists(chromium))
    GTEST_SKIP() << "no Chromium (" << chromium
                 << " does not exist): the report's browser test needs it; scripts/install-deps.sh installs it";
  TempDir dir;
  std::string scene = testing::small_scene_json(48, 32);
  const std::string sun = R"("sun": {"altitude_deg": 40, "azimuth_deg": 135})";
  scene.replace(scene.find(sun), sun.size(),
                R"("site": {"latitude_deg": 48.2, "longitude_deg": 16.37}, "time": "2026-06-21T14:00+02:00")");
  const auto scene_file = dir.write("scene.json", scene);
  const auto r = run_skylit("render " + quoted(scene_file) + " --quiet --set render.exr_layers=true -o " +
                            quoted(dir.path() / "v.exr") + " --report " + quoted(dir.path() / "report.html"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const std::string html = read_file(dir.path() / "report.html");
  EXPECT_NE(html.find("48.20° N, 16.37° E"), std::string::npos);
  EXPECT_NE(html.find("2026-06-21T14:00+02:00"), std::string::npos);

  // A pixel on the box and one on the ground plane, read through every image, in one
  // Chromium session.
  const XyzImage exr = read_image(dir.path() / "v.exr");
  const std::vector<float> lux = exr_illuminance(dir.path() / "v.exr");
  const std::vector<std::pair<int, int>> pixels{{24, 14}, {5, 29}};
  const testing::PageResult page =
      testing::run_page_script("report_readout.mjs", chromium, dir.path() / "report.html", "24 14 5 29");
  ASSERT_EQ(page.command.exit_status, 0) << page.command.output;
  const nlohmann::json& result = page.json;
  ASSERT_TRUE(result.is_object()) << page.command.output;
  EXPECT_TRUE(result["errors"].empty()) << result["errors"].dump();
  ASSERT_EQ(result["images"].size(), 3u);  // the display image, luminance and illuminance in false colour
  for (const auto& image : result["images"]) {
    EXPECT_TRUE(image["complete"].get<bool>()) << image.dump();
    EXPECT_GT(image["naturalWidth"].get<int>(), 0) << image.dump();
  }
  ASSERT_EQ(result["readouts"].size(), 3 * pixels.size());
  for (std::size_t i = 0; i < result["readouts"].size(); ++i) {
    const auto& readout = result["readouts"][i];
    const auto [x, y] = pixels[i / 3];
    const double expected = exr.at(x, y).y;
    const double expected_lux = lux[std::size_t(y) * exr.width + x];
    ASSERT_GT(expected, 1.0);  // daylight: well inside the code's range
    ASSERT_GT(expected_lux, 1.0);
    EXPECT_EQ(readout["x"], std::to_string(x));
    EXPECT_EQ(readout["y"], std::to_string(y));
    // The decoded values: within the 16-bit code's stated precision (0.029 %).
    const double decoded = std::stod(readout["luminance"].get<std::string>());
    EXPECT_NEAR(decoded, expected, LuminanceCodeScale::kRelativePrecision * expected) << readout.dump();
    const double decoded_lux = std::stod(readout["illuminance"].get<std::string>());
    EXPECT_NEAR(decoded_lux, expected_lux, LuminanceCodeScale::kRelativePrecision * expected_lux) << readout.dump();
    // The text shows four significant digits: within the precision plus half a unit
    // of the fourth digit (at most 0.05 %).
    const std::string text = readout["text"];
    const std::size_t at = text.find("luminance ");
    ASSERT_NE(at, std::string::npos) << text;
    const double shown = std::stod(text.substr(at + 10));
    EXPECT_NEAR(shown, expected, (LuminanceCodeScale::kRelativePrecision + 5e-4) * expected) << text;
  }
}

}  // namespace
}  // namespace skylit
