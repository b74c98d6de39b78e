// The scene file's `lights` (io/light_reader.cpp): what a valid list gives the
// renderer, and one clear error naming the file and place for each kind of mistake.
#include <gtest/gtest.h>

#include <string>

#include "../test_support.h"
#include "skylit/core/error.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_report.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

using testing::TempDir;

// The small test scene with `lights` added before its last closing brace.
std::string with_lights(const std::string& lights) { return testing::small_scene_with("lights", lights); }

std::string load_error(const TempDir& dir, const std::string& text) {
  return testing::input_error_of([&] { load_scene(dir.write("scene.json", text)); });
}

const char* kIsotropicIes = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 50\n0 90\n0\n500 500\n";

TEST(SceneLights, ReadsFilesShapesLumensAndSpectra) {
  TempDir dir;
  dir.write("iso.ies", kIsotropicIes);
  const Scene scene = load_scene(dir.write("scene.json", with_lights(R"([
        {"name": "a", "position": [1, 2, 6], "ies": "iso.ies", "lamp": "high_pressure_sodium"},
        {"position": [0, 0, 1], "aim": [0, -1, 0], "shape": "spot", "candela": 20000, "inner_deg": 5,
         "outer_deg": 12, "lamp": "halogen"},
        {"position": [0, 0, 9], "shape": "isotropic", "candela": 10, "lumens": 1000, "lamp": "led",
         "temperature_k": 3000}])")));
  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_EQ(scene.lights[0].name, "a");
  EXPECT_DOUBLE_EQ(scene.lights[0].luminaire.intensity({0, 0, -1}), 500);  // γ 0–90 measured
  EXPECT_DOUBLE_EQ(scene.lights[0].luminaire.intensity({0, 0, 1}), 0);     // none upward
  EXPECT_NEAR(scene.lights[1].luminaire.intensity({0, -1, 0}), 20000, 1e-9);
  EXPECT_NEAR(scene.lights[2].luminaire.distribution().luminous_flux(), 1000, 1e-3);  // rescaled
  for (const SceneLight& light : scene.lights) EXPECT_NEAR(luminance(light.spectrum_per_candela), 1.0, 1e-6);
}

TEST(SceneLights, InfoSaysEachSourcesFluxPeakAndHeights) {
  TempDir dir;
  dir.write("iso.ies", kIsotropicIes);
  const Scene scene = load_scene(dir.write("scene.json", with_lights(R"([
        {"name": "a", "position": [1, 2, 6], "ies": "iso.ies", "lamp": "led"},
        {"name": "b", "position": [3, 2, 7.5], "ies": "iso.ies", "lamp": "led"},
        {"name": "c", "position": [0, 0, 9], "shape": "isotropic", "candela": 10, "lumens": 1000, "lamp": "led"}])")));
  const std::string text = describe_lights(scene);
  // 500 cd over the lower half sphere: 500 · 2π = 3141.6 lm, from the file's table.
  EXPECT_NE(text.find("lights: 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("'a' and 1 more: 'iso.ies' (LM-63-2002)\n    3142 lm each, peak 500 cd; at z 6.00 to 7.50 m\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("'c': isotropic shape, scaled to 1000 lm\n    1000 lm each, peak 80 cd; at z 9.00 m\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(describe_lights(load_scene(dir.write("none.json", with_lights("[]")))), "");
}

TEST(SceneLights, MistakesNameTheFileAndPlace) {
  TempDir dir;
  dir.write("bad.ies", "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 50\n0 abc\n0\n1 1\n");
  dir.write("down.csv", "wavelength_nm,power\n500,1\n400,1\n");
  // Rows of different lengths: a later row once added a column, so the table's
  // wavelength and power columns differed in length (a heap overflow when read).
  dir.write("ragged.csv", "wavelength_nm,power\n400\n500,1\n");
  dir.write("short.csv", "wavelength_nm,power\n400,1\n500\n");
  struct Case {
    std::string lights, expected;
  };
  const Case cases[] = {
      {R"([{"position": [0, 0, 5], "lamp": "led"}])", "lights[0]: a light needs exactly one of"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "ies": "x.ies", "lamp": "led"}])",
       "exactly one of"},
      {R"([{"position": [0, 0, 5], "ies": "missing.ies", "lamp": "led"}])", "missing.ies:1: cannot open the IES file"},
      {R"([{"position": [0, 0, 5], "ies": "bad.ies", "lamp": "led"}])", "bad.ies:5:"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "sodium"}])",
       "lights[0].lamp: expected a lamp type"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "led", "temperature_k": 2000}])",
       "lights[0].temperature_k"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "halogen", "temperature_k": 3000}])",
       "only an led or a blackbody"},
      {R"([{"position": [0, 0, 5], "shape": "spot", "candela": 1, "inner_deg": 20, "outer_deg": 10, "lamp": "led"}])",
       "outer_deg must not be below inner_deg"},
      {R"([{"position": [0, 0, 5], "ies": "x.ies", "inner_deg": 5, "lamp": "led"}])",
       "only a spot shape has cone angles"},
      {R"([{"position": [0, 0, 5], "aim": [0, 0, 0], "shape": "isotropic", "candela": 1, "lamp": "led"}])",
       "lights[0].aim"},
      {R"([{"position": [0, 0, 5], "aim": [1e200, 1e200, 1e200], "shape": "isotropic", "candela": 1, "lamp": "led"}])",
       "lights[0].aim"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "table", "spectrum_file": "down.csv"}])",
       "down.csv:3: wavelengths must be finite and strictly increasing"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "table", "spectrum_file": "ragged.csv"}])",
       "ragged.csv:3: expected 1 columns, found 2"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "table", "spectrum_file": "short.csv"}])",
       "short.csv:3: expected 2 columns, found 1"},
      {R"([{"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "led", "colour": 1}])",
       "lights[0].colour: unknown key"},
  };
  for (const Case& c : cases) {
    const std::string message = load_error(dir, with_lights(c.lights));
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.lights << "\n  gave: " << message;
  }
}

}  // namespace
}  // namespace skylit
