#include "skylit/io/scene/json_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/scene/scene.h"

namespace skylit {

namespace {
std::string join_words(std::span<const std::string_view> words) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += ", ";
    out += w;
  }
  return out;
}

std::string child_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}
}  // namespace

JsonReader::JsonReader(const nlohmann::json& value, std::string source, std::string path)
    : value_(&value), source_(std::move(source)), path_(std::move(path)) {}

void JsonReader::fail(const std::string& message) const {
  throw InputError(source_ + ": " + (path_.empty() ? std::string("(top level)") : path_) + ": " + message);
}

void JsonReader::fail_expected(const std::string& what) const {
  fail("expected " + what + ", found " + describe_json_value(*value_));
}

void JsonReader::expect_object() const {
  if (!value_->is_object()) fail_expected("an object");
}

bool JsonReader::has(std::string_view key) const {
  expect_object();
  return value_->contains(key);
}

JsonReader JsonReader::required(std::string_view key) const {
  expect_object();
  const auto it = value_->find(key);
  if (it == value_->end()) fail("missing required key '" + std::string(key) + "'");
  return JsonReader(*it, source_, child_path(path_, key));
}

std::optional<JsonReader> JsonReader::optional(std::string_view key) const {
  expect_object();
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return JsonReader(*it, source_, child_path(path_, key));
}

void JsonReader::allow_only(std::initializer_list<std::string_view> allowed) const {
  expect_object();
  for (const auto& [key, unused] : value_->items()) {
    bool known = false;
    for (std::string_view a : allowed) known = known || a == key;
    if (!known)
      JsonReader(unused, source_, child_path(path_, key))
          .fail("unknown key; expected one of: " + join_words({allowed.begin(), allowed.size()}));
  }
}

std::vector<std::pair<std::string, JsonReader>> JsonReader::members() const {
  expect_object();
  std::vector<std::pair<std::string, JsonReader>> out;
  for (const auto& [key, value] : value_->items())
    out.emplace_back(key, JsonReader(value, source_, child_path(path_, key)));
  return out;
}

std::vector<JsonReader> JsonReader::elements() const {
  if (!value_->is_array()) fail_expected("an array");
  std::vector<JsonReader> out;
  for (size_t i = 0; i < value_->size(); ++i)
    out.emplace_back((*value_)[i], source_, path_ + "[" + std::to_string(i) + "]");
  return out;
}

double JsonReader::number() const {
  if (!value_->is_number()) fail_expected("a number");
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail_expected("a finite number");
  return v;
}

double JsonReader::number_in(double lo, double hi) const {
  const double v = number();
  if (v < lo || v > hi) {
    std::ostringstream range;
    range << "a number from " << lo << " to " << hi;
    fail_expected(range.str());
  }
  return v;
}

int JsonReader::integer_in(int lo, int hi) const {
  if (!value_->is_number_integer())
    fail_expected("an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  const auto v = value_->get<long long>();
  if (v < lo || v > hi) fail_expected("an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(v);
}

bool JsonReader::boolean() const {
  if (!value_->is_boolean()) fail_expected("true or false");
  return value_->get<bool>();
}

std::string JsonReader::string() const {
  if (!value_->is_string()) fail_expected("a string");
  return value_->get<std::string>();
}

std::string JsonReader::one_of(std::initializer_list<std::string_view> words) const {
  return one_of(std::span<const std::string_view>(words.begin(), words.size()));
}

std::string JsonReader::one_of(std::span<const std::string_view> words) const {
  if (value_->is_string()) {
    std::string s = value_->get<std::string>();  // not const: returned by move
    for (std::string_view w : words)
      if (w == s) return s;
  }
  fail_expected("one of: " + join_words(words));
}

Vec3 JsonReader::vec3() const {
  if (!value_->is_array() || value_->size() != 3) fail_expected("an array of 3 numbers");
  const auto e = elements();
  return {e[0].number(), e[1].number(), e[2].number()};
}

Vec3 JsonReader::point_m() const {
  const Vec3 p = vec3();
  for (const double c : {p.x, p.y, p.z})
    if (!(std::abs(c) <= kSceneExtentM)) fail_expected("a point [x, y, z] in metres, each within ±1e7 (10,000 km)");
  return p;
}

std::string describe_json_value(const nlohmann::json& value) {
  // A string set by --set can hold bytes that are not UTF-8: shown replaced (U+FFFD),
  // not thrown as nlohmann's type_error (found by the scene fuzz target).
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

namespace {

// "<line>:<column>" of a byte offset in a text (both 1-based).
std::string line_and_column(const std::string& text, size_t offset) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// nlohmann's description without its "[json.exception...] ...: " prefix, and with the
// text it quotes ("last read: '...'", which may be a line of any file named by mistake)
// cut to a short excerpt (issue 19, item 16).
std::string description_of(const nlohmann::json::exception& e) {
  std::string what = e.what();
  const size_t detail = what.find(": ");
  if (detail != std::string::npos) what = what.substr(detail + 2);
  const std::string marker = "last read: '";
  const size_t start = what.find(marker);
  if (start == std::string::npos) return what;
  const size_t token = start + marker.size();
  size_t end = what.find("'; expected", token);
  if (end == std::string::npos) end = what.rfind('\'');
  if (end == std::string::npos || end < token) end = what.size();
  const std::string rest = end < what.size() ? what.substr(end + 1) : "";
  return what.substr(0, start) + "last read: " + quote_excerpt(std::string_view(what).substr(token, end - token)) +
         rest;
}

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& source) {
  try {
    return nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the 1-based offset of the character that made the text invalid.
    const size_t offset = e.byte == 0 ? 0 : e.byte - 1;
    throw InputError(source + ":" + line_and_column(text, offset) + ": invalid JSON: " + description_of(e));
  } catch (const nlohmann::json::out_of_range& e) {
    // A number too large for a double (1e400): nlohmann names the token but not where
    // it is; the place is its first occurrence in the text.
    std::string what = description_of(e);
    const size_t open = what.find('\''), close = what.rfind('\'');
    const std::string token = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const size_t at = token.empty() ? std::string::npos : text.find(token);
    const std::string place = at == std::string::npos ? "" : ":" + line_and_column(text, at);
    throw InputError(source + place + ": invalid JSON: a number too large for a double (" +
                     describe_json_value(nlohmann::json(token.substr(0, 30))) + ")");
  }
}

}  // namespace skylit
