// Scene files with `--set` overrides (io/scene/scene_loader.h, scene_overrides.h),
// read as load_scene reads them. The input is the scene's text, then optionally a
// line "--set" and one override `path=value` per line after it.
#include <vector>

#include "fuzz_support.h"
#include "skylit/io/scene/json_reader.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/io/scene/scene_overrides.h"
#include "skylit/io/scene/scene_parts.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input = skylit::fuzz::text_of(data, size);
  constexpr std::string_view kSeparator = "\n--set\n";
  const size_t split = input.find(kSeparator);
  const std::string scene_text(input.substr(0, split));
  std::vector<std::string> overrides;
  if (split != std::string_view::npos) {
    std::string_view rest = input.substr(split + kSeparator.size());
    while (!rest.empty()) {
      const size_t end = rest.find('\n');
      overrides.emplace_back(rest.substr(0, end));
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
  }
  // Mesh, IES and spectrum files named by the scene are looked for in an empty
  // folder: those parsers have targets of their own.
  const auto base_dir = skylit::fuzz::work_dir();
  return skylit::fuzz::accept_input_errors([&] {
    nlohmann::json document = skylit::parse_json_text(scene_text, "fuzz.json");
    for (const std::string& assignment : overrides) skylit::apply_override(document, assignment);
    skylit::scene_from_json(document, "fuzz.json", base_dir);
  });
}
