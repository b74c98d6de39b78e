// A lamp's spectrum table (a CSV file named by `spectrum_file` of a lamp of type
// `table`, io/scene/light_reader.cpp, spectrum/tabulated.h), read the way a scene
// reads it: the bytes are the table, in a small scene with one such lamp.
#include "fuzz_support.h"
#include "skylit/io/scene/json_reader.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_parts.h"

namespace {
const char* kScene = R"({
  "camera": {"position": [0, -20, 2], "look_at": [0, 0, 3], "vertical_fov_deg": 60},
  "sun": {"altitude_deg": -10, "azimuth_deg": 135},
  "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
  "objects": [{"type": "plane", "material": "white", "size_m": 200}],
  "lights": [{"position": [0, 0, 5], "shape": "isotropic", "candela": 100, "lamp": "table",
              "spectrum_file": "lamp.csv"}]
})";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  skylit::fuzz::write_file("lamp.csv", skylit::fuzz::text_of(data, size));
  static const nlohmann::json document = skylit::parse_json_text(kScene, "fuzz.json");
  return skylit::fuzz::accept_input_errors(
      [&] { skylit::scene_from_json(document, "fuzz.json", skylit::fuzz::work_dir()); });
}
