#include "skylit/io/scene/scene_overrides.h"

#include <charconv>

#include "skylit/core/error.h"

namespace skylit {

namespace {
std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> keys;
  size_t start = 0;
  while (true) {
    const size_t dot = path.find('.', start);
    keys.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return keys;
}

bool parse_index(const std::string& key, size_t& index) {
  const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), index);
  return ec == std::errc() && end == key.data() + key.size();
}
}  // namespace

void apply_override(nlohmann::json& document, const std::string& assignment) {
  const auto fail = [&](const std::string& why) { throw InputError("--set " + assignment + ": " + why); };
  const size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) fail("expected path=value, e.g. sun.altitude_deg=4");
  const std::string path = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);

  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;  // a bare word such as `tile`

  nlohmann::json* node = &document;
  for (const std::string& key : split_path(path)) {
    if (key.empty()) fail("empty key in the path");
    if (node->is_array()) {
      size_t index = 0;
      if (!parse_index(key, index) || index >= node->size())
        fail("'" + key + "' is not an index of an array of " + std::to_string(node->size()) + " elements");
      node = &(*node)[index];
    } else {
      if (node->is_null()) *node = nlohmann::json::object();
      if (!node->is_object()) fail("'" + key + "' is inside a value that is neither an object nor an array");
      node = &(*node)[key];
    }
  }
  *node = std::move(value);
}

}  // namespace skylit
