// Bad input in scene files that got through before issue 19: each case is refused by
// the reader with one line naming the file and the place (an InputError, exit status 2),
// instead of crashing, hanging, filling the memory or making NaN pixels later.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "../test_support.h"
#include "skylit/clouds/cloud_layer.h"
#include "skylit/core/text_file.h"
#include "skylit/io/scene/scene_loader.h"

namespace skylit {
namespace {

using testing::TempDir;

std::string with(const std::string& key, const std::string& value) { return testing::small_scene_with(key, value); }

// The small test scene with one more object.
std::string with_object(const std::string& object) {
  std::string text = testing::small_scene_json();
  text.insert(text.find("\n  ],"), ",\n    " + object);
  return text;
}

std::string load_error(const TempDir& dir, const std::string& text) {
  return testing::input_error_of([&] { load_scene(dir.write("scene.json", text)); });
}

const char* kIsotropicIes = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 50\n0 90\n0\n";

TEST(BadInputScene, FogDensityThatOverflowsIsRefusedWhereItIsSet) {
  // Item 4: a scale height of −1 mm makes the density e^(60000) at the layer's top; a
  // layer far below the ground with a positive scale height, e^(1000) at its bottom.
  TempDir dir;
  for (const char* fog : {R"({"scale_height_m": -0.001})", R"({"bottom_m": -10000, "top_m": -9000})"}) {
    const std::string error = load_error(dir, with("fog", fog));
    EXPECT_NE(error.find("scene.json: fog: the fog's density at its densest point"), std::string::npos) << error;
    EXPECT_NE(error.find("over the limit of 1e6"), std::string::npos) << error;
  }
  // A density within bounds whose extinction is not: 400 × 1 m⁻¹.
  const std::string error = load_error(dir, with("fog", R"({"density_at_ground": 400, "scale_height_m": 1e6,
      "unit_density_extinction_per_m": 1})"));
  EXPECT_NE(error.find("scene.json: fog: the fog's extinction at its densest point (the layer's bottom) would be 400 "
                       "per metre, over the limit of 10"),
            std::string::npos)
      << error;
  // The paper's dense fog (Fig. 8a) and a thick one at the limit's edge stay accepted.
  EXPECT_EQ(load_error(dir, with("fog", R"({"density_at_ground": 0.59, "scale_height_m": 10})")), "");
  EXPECT_EQ(load_error(dir, with("fog", R"({"density_at_ground": 400, "scale_height_m": 1e6})")), "");
}

TEST(BadInputScene, PhotometricFilesOverTheCandelaLimitAreRefusedOnTheirLine) {
  // Item 5: a candela value of 1e308 is finite, and was accepted; shapes stop at 1e9.
  TempDir dir;
  dir.write("huge.ies", std::string(kIsotropicIes) + "1e308 500\n");
  std::string error = load_error(dir, with("lights", R"([{"position": [0, 0, 5], "ies": "huge.ies", "lamp": "led"}])"));
  EXPECT_NE(error.find("huge.ies:7: a candela value"), std::string::npos) << error;
  EXPECT_NE(error.find("1e9 cd"), std::string::npos) << error;
  // A multiplier that lifts an ordinary value past the limit is refused too.
  dir.write("scaled.ies", "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1e7 2 1 1 2 0 0 0\n1 1 50\n0 90\n0\n500 500\n");
  error = load_error(dir, with("lights", R"([{"position": [0, 0, 5], "ies": "scaled.ies", "lamp": "led"}])"));
  EXPECT_NE(error.find("scaled.ies:7:"), std::string::npos) << error;
  // Scaling a distribution to a flux whose peak would pass the limit.
  error = load_error(dir, with("lights", R"([{"position": [0, 0, 5], "shape": "spot", "candela": 1, "inner_deg": 0,
      "outer_deg": 1, "lumens": 1e9, "lamp": "led"}])"));
  EXPECT_NE(error.find("lights[0].lumens: this flux"), std::string::npos) << error;
}

TEST(BadInputScene, PlacedCoordinatesAreCheckedWhereTheyAreRead) {
  // Items 7 and 17: each used to pass the reader and fail later in the ray tracer (exit
  // 1), or as "the view is vertical" when the camera's distance overflowed.
  TempDir dir;
  dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("wide.obj", "v 0 0 0\nv 1e10 0 0\nv 0 1 0\nf 1 2 3\n");
  const struct {
    std::string scene, place;
  } cases[] = {
      {with_object(R"({"type": "box", "material": "white", "min": [0, 0, 0], "max": [1e39, 1, 1]})"),
       "objects[2].max: expected a point"},
      {with_object(R"({"type": "plane", "material": "white", "center": [1e300, 0, 0]})"),
       "objects[2].center: expected a point"},
      {with_object(R"({"type": "mesh", "material": "white", "file": "tri.obj", "transform": {"scale": 1e39}})"),
       "objects[2].transform.scale: scale factors"},
      {with_object(R"({"type": "mesh", "material": "white", "file": "wide.obj",
                      "transform": {"scale": 1e6, "translate": [9.5e6, 0, 0]}})"),
       "objects[2].transform: vertex 1 of the mesh lies beyond"},
      {with_object(R"({"type": "box", "material": "white", "center": [0, 0, 0], "size": [1, 1, 1e30]})"),
       "objects[2].size: expected three sizes"},
      {with("lights", R"([{"position": [0, 0, 1e20], "shape": "isotropic", "candela": 1, "lamp": "led"}])"),
       "lights[0].position: expected a point"},
  };
  for (const auto& c : cases) {
    const std::string error = load_error(dir, c.scene);
    EXPECT_NE(error.find("scene.json: " + c.place), std::string::npos) << error;
  }
  std::string camera = testing::small_scene_json();
  camera.replace(camera.find("[0, -20, 2]"), 11, "[1e300, 0, 1]");
  const std::string error = load_error(dir, camera);
  EXPECT_NE(error.find("camera.position: expected a point [x, y, z] in metres, each within"), std::string::npos)
      << error;
  EXPECT_EQ(error.find("vertical"), std::string::npos) << error;
}

TEST(BadInputScene, GltfBufferThatIsAFolderOrAFifoIsRefused) {
  // Item 8: a uri of "." made tinygltf allocate the folder's size (bad_alloc, exit 1);
  // item 9: a FIFO blocked forever.
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir.path() / "pipe.bin").c_str(), 0600), 0);
  for (const char* uri : {".", "pipe.bin"}) {
    dir.write("m.gltf", std::string(R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 44, "uri": ")") + uri +
                            R"("}], "meshes": [], "nodes": []})");
    const std::string error =
        load_error(dir, with_object(R"({"type": "mesh", "material": "white", "file": "m.gltf"})"));
    EXPECT_NE(error.find("m.gltf: cannot read glTF:"), std::string::npos) << uri << ": " << error;
    EXPECT_NE(error.find("not a regular file"), std::string::npos) << uri << ": " << error;
  }
}

TEST(BadInputScene, DevicesFifosAndHugeFilesAreNotReadAsText) {
  // Item 9: /dev/zero was read until 4 GB; a FIFO blocked. Refused before reading.
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir.path() / "fifo").c_str(), 0600), 0);
  for (const std::string& file : {std::string("/dev/zero"), (dir.path() / "fifo").string()}) {
    for (const std::string& light :
         {R"({"position": [0, 0, 5], "ies": ")" + file + R"(", "lamp": "led"})",
          R"({"position": [0, 0, 5], "ldt": ")" + file + R"(", "lamp": "led"})",
          R"({"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "table", "spectrum_file": ")" + file +
              R"("})"}) {
      const std::string error = load_error(dir, with("lights", "[" + light + "]"));
      EXPECT_NE(error.find(file + ":1: cannot read the"), std::string::npos) << error;
      EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
    }
    const std::string error = testing::input_error_of([&] { load_scene(file); });
    EXPECT_NE(error.find(file + ":1: cannot read the scene file: not a regular file"), std::string::npos) << error;
  }
  // Over the documented limit (64 MiB): a sparse file, refused by its size unread.
  const auto big = dir.path() / "big.json";
  std::filesystem::resize_file(dir.write("big.json", "{"), kMaxTextFileBytes + 1);
  const std::string error = testing::input_error_of([&] { load_scene(big); });
  EXPECT_NE(error.find("big.json:1: cannot read the scene file: larger than the limit of 64 MiB"), std::string::npos)
      << error;
}

TEST(BadInputScene, PixelCountIsBoundedBeforeRendering) {
  // Item 10: 16384 × 16384 was accepted and needed ~29 GB when rendered.
  TempDir dir;
  std::string text = testing::small_scene_json(16384, 16384);
  std::string error = load_error(dir, text);
  EXPECT_NE(error.find("scene.json: render: width × height is 268435456 pixels, over the limit"), std::string::npos)
      << error;
  EXPECT_NE(error.find("300 bytes per pixel"), std::string::npos) << error;
  EXPECT_EQ(load_error(dir, testing::small_scene_json(7680, 4320)), "");
  EXPECT_EQ(load_error(dir, testing::small_scene_json(16384, 64)), "");  // a panorama strip
}

TEST(BadInputScene, CloudLayersTooManyToRenderAreRefusedWithTheReason) {
  // Item 11: 1 m clouds over the default region are ~10^8 clouds (the generator stopped
  // at 20,000, which still ran over 120 s and 1.6 GB at 64 × 36).
  TempDir dir;
  for (const char* layer : {R"({"altitude_m": 1500, "coverage": 0.3, "min_semi_axis_m": 1, "max_semi_axis_m": 1})",
                            R"({"altitude_m": 1500, "coverage": 0.3, "half_extent_m": 1e5})"}) {
    const std::string error = load_error(dir, with("clouds", layer));
    EXPECT_NE(error.find("scene.json: clouds: this layer would hold about"), std::string::npos) << error;
    EXPECT_NE(error.find("over the limit of 500"), std::string::npos) << error;
  }
  // The documented default layer is accepted, and the estimate is what generate() makes
  // (within 4 standard deviations of a Poisson count).
  EXPECT_EQ(load_error(dir, with("clouds", R"({"altitude_m": 1500, "coverage": 0.3})")), "");
  CloudLayerSettings settings;
  const double expected = expected_generated_cloud_count(settings);
  double made = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    settings.seed = seed;
    made += static_cast<double>(CloudLayer::generate(settings).clouds().size());
  }
  EXPECT_NEAR(made / 8, expected, 4 * std::sqrt(expected / 8)) << expected;
}

TEST(BadInputScene, MessagesQuoteOnlyAShortPieceOfTheFileNamed) {
  // Item 16: an "ldt" or a spectrum table naming some other file printed a line of it.
  TempDir dir;
  const std::string secret = "a line of some private file that must not be shown whole";
  dir.write("private.txt", secret + "\n" + secret + "\n" + secret + "\n");
  for (const char* light : {R"({"position": [0, 0, 5], "ldt": "private.txt", "lamp": "led"})",
                            R"({"position": [0, 0, 5], "ies": "private.txt", "lamp": "led"})",
                            R"({"position": [0, 0, 5], "shape": "isotropic", "candela": 1, "lamp": "table",
                                "spectrum_file": "private.txt"})"}) {
    const std::string error = load_error(dir, with("lights", std::string("[") + light + "]"));
    EXPECT_NE(error.find("private.txt:"), std::string::npos) << error;
    EXPECT_EQ(error.find(secret.substr(0, 21)), std::string::npos) << error;
    EXPECT_EQ(error.find(secret.substr(20, 21)), std::string::npos) << error;
  }
  // The same file given as the scene: nlohmann's "last read" is cut too.
  const std::string error = testing::input_error_of([&] { load_scene(dir.path() / "private.txt"); });
  EXPECT_NE(error.find("private.txt:1:"), std::string::npos) << error;
  EXPECT_EQ(error.find(secret.substr(0, 21)), std::string::npos) << error;
  // A glTF buffer pointing at another file: its size is not told.
  dir.write("m.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4, "uri": "private.txt"}]})");
  const std::string gltf = load_error(dir, with_object(R"({"type": "mesh", "material": "white", "file": "m.gltf"})"));
  const size_t message = gltf.find("m.gltf: cannot read glTF");
  ASSERT_NE(message, std::string::npos) << gltf;
  // After the file's name: the temporary folder's random name may hold the digits.
  EXPECT_EQ(gltf.find(std::to_string(3 * (secret.size() + 1)), message), std::string::npos) << gltf;
}

}  // namespace
}  // namespace skylit
