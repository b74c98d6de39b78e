// Checked reading of JSON values for scene files: every accessor either returns a
// value of the expected kind or throws an InputError that names the file, the JSON
// path (e.g. `objects[2].size`) and what was expected. Unknown keys are errors, so a
// typo never passes silently.
#pragma once

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "skylit/core/vec3.h"

namespace skylit {

class JsonReader {
 public:
  // `source` names the document in messages (the scene file's path).
  JsonReader(const nlohmann::json& value, std::string source, std::string path = "");

  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }
  const nlohmann::json& raw() const { return *value_; }

  // Throws "<source>: <path>: <message>".
  [[noreturn]] void fail(const std::string& message) const;
  // Throws "<source>: <path>: expected <what>, found <the value>".
  [[noreturn]] void fail_expected(const std::string& what) const;

  // Objects.
  bool has(std::string_view key) const;
  JsonReader required(std::string_view key) const;
  std::optional<JsonReader> optional(std::string_view key) const;
  // Fails on the first key not in `allowed`, listing the allowed ones.
  void allow_only(std::initializer_list<std::string_view> allowed) const;
  std::vector<std::pair<std::string, JsonReader>> members() const;

  // Arrays.
  std::vector<JsonReader> elements() const;

  // Scalars.
  double number() const;
  // A finite number in [lo, hi].
  double number_in(double lo, double hi) const;
  int integer_in(int lo, int hi) const;
  bool boolean() const;
  std::string string() const;
  // One of the given words; the message lists them.
  std::string one_of(std::initializer_list<std::string_view> words) const;
  std::string one_of(std::span<const std::string_view> words) const;
  Vec3 vec3() const;
  // A point [x, y, z] in metres in the scene, each within ±kSceneExtentM (scene.h).
  Vec3 point_m() const;

  bool is_number() const { return value_->is_number(); }
  bool is_string() const { return value_->is_string(); }
  bool is_array() const { return value_->is_array(); }
  bool is_object() const { return value_->is_object(); }

 private:
  void expect_object() const;
  const nlohmann::json* value_;
  std::string source_;
  std::string path_;
};

// A short rendering of a JSON value for messages, cut at about 40 characters.
std::string describe_json_value(const nlohmann::json& value);

// Parses JSON text (comments allowed); a syntax error becomes an InputError
// "<source>:<line>:<column>: <what is wrong>".
nlohmann::json parse_json_text(const std::string& text, const std::string& source);

}  // namespace skylit
