#include "skylit/io/model/obj_parser.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <map>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"

namespace skylit {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

const char* skip_blanks(const char* p, const char* stop) {
  while (p < stop && blank(*p)) ++p;
  return p;
}

// A number as from_chars reads it, after an optional '+' (which it does not take).
template <typename T>
std::from_chars_result read_number(const char* p, const char* stop, T& value) {
  if (p < stop && *p == '+') ++p;
  return std::from_chars(p, stop, value);
}

// Up to N numbers for `vt` and `vn`, as tinyobjloader reads them: one that is missing
// or unreadable is 0 (a non-finite or unreadable coordinate is handled by its user).
template <size_t N>
std::array<float, N> lenient_floats(const char* p, const char* stop) {
  std::array<float, N> out{};
  for (float& c : out) {
    p = skip_blanks(p, stop);
    float value = 0;
    const auto [next, ec] = read_number(p, stop, value);
    if (ec == std::errc()) c = value;
    p = next;
    while (p < stop && !blank(*p)) ++p;  // past anything unreadable
  }
  return out;
}

// A 1-based or negative (relative) OBJ index, 0-based against `count` elements read so far.
int32_t resolved(long index, size_t count) {
  return static_cast<int32_t>(index > 0 ? index - 1 : static_cast<long>(count) + index);
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& file_name) : text_(text), file_name_(file_name) {}

  ObjGeometry parse() {
    const char* p = text_.data();
    const char* const end = p + text_.size();
    while (p < end) {
      // A line ends at "\n", "\r\n" or a lone "\r" (as tinyobjloader reads them).
      const char* stop = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
      if (stop == nullptr) stop = end;
      const char* next = stop + (stop < end ? 1 : 0);
      if (const char* cr = static_cast<const char*>(std::memchr(p, '\r', static_cast<size_t>(stop - p)));
          cr != nullptr && cr + 1 != stop) {
        stop = cr;
        next = cr + 1;
      }
      ++line_;
      // A line whose last character (before a "\r") is a backslash goes on in the next
      // (the OBJ specification's continuation; long faces are written so).
      const char* last = stop;
      while (last > p && (last[-1] == '\r' || blank(last[-1]))) --last;
      if (last > p && last[-1] == '\\') {
        continued_.append(p, last - 1).push_back(' ');
      } else if (!continued_.empty()) {
        continued_.append(p, stop);
        const std::string joined = std::move(continued_);
        continued_.clear();
        line(skip_blanks(joined.data(), joined.data() + joined.size()), joined.data() + joined.size());
      } else {
        line(skip_blanks(p, stop), stop);
      }
      p = next;
    }
    if (!continued_.empty())
      line(skip_blanks(continued_.data(), continued_.data() + continued_.size()),
           continued_.data() + continued_.size());
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what, const char* p, const char* stop) const {
    throw InputError(file_name_ + ":" + std::to_string(line_) + ": " + what + ": " +
                     std::string(p, stop).substr(0, 40));
  }

  static bool keyword(const char* p, const char* stop, std::string_view word) {
    const auto n = static_cast<ptrdiff_t>(word.size());
    return stop - p > n && std::string_view(p, word.size()) == word && blank(p[n]);
  }

  void line(const char* p, const char* stop) {
    if (p == stop) return;
    if (keyword(p, stop, "v"))
      vertex(p + 2, stop);
    else if (keyword(p, stop, "vt"))
      out_.texcoords.push_back(lenient_floats<2>(p + 3, stop));
    else if (keyword(p, stop, "vn"))
      out_.normals.push_back(lenient_floats<3>(p + 3, stop));
    else if (keyword(p, stop, "f"))
      face(p + 2, stop);
    else if (std::string_view(p, static_cast<size_t>(std::min<ptrdiff_t>(stop - p, 6))) == "usemtl")
      use_material(p + 6, stop);
    else if (keyword(p, stop, "mtllib"))
      out_.material_libraries.push_back(trimmed(p + 7, stop));
    else if (keyword(p, stop, "p") || keyword(p, stop, "l"))
      ++out_.points_and_lines;
  }

  // Three finite numbers (a fourth, w, or vertex colours after them are ignored).
  void vertex(const char* p, const char* stop) {
    double xyz[3];
    for (double& c : xyz) {
      p = skip_blanks(p, stop);
      const auto [next, ec] = read_number(p, stop, c);
      if (ec != std::errc() || !std::isfinite(c) || (next < stop && !blank(*next)))
        fail("a vertex needs three finite numbers", p, stop);
      p = next;
    }
    out_.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  // Corners "v", "v/vt", "v//vn" or "v/vt/vn", an empty field standing for none ("1//",
  // "2/2/", "3/" as some exporters write them); after a number, anything up to the next
  // '/' or blank is skipped, as tinyobjloader does.
  void face(const char* p, const char* stop) {
    const auto field_here = [&] { return p < stop && *p != '/' && !blank(*p); };
    for (p = skip_blanks(p, stop); p < stop; p = skip_blanks(p, stop)) {
      ObjCorner corner;
      corner.vertex = index(p, stop, out_.positions.size());
      if (p < stop && *p == '/') {
        ++p;
        if (field_here()) corner.texcoord = index(p, stop, out_.texcoords.size());
        if (p < stop && *p == '/') {
          ++p;
          if (field_here()) corner.normal = index(p, stop, out_.normals.size());
        }
      }
      out_.corners.push_back(corner);
    }
    out_.face_ends.push_back(static_cast<uint32_t>(out_.corners.size()));
    out_.face_material_names.push_back(material_);
  }

  int32_t index(const char*& p, const char* stop, size_t count) {
    long value = 0;
    const auto [next, ec] = read_number(p, stop, value);
    if (ec != std::errc() || value == 0 || value > INT32_MAX || value < INT32_MIN)
      fail("a face corner needs an index counted from 1 (or back from -1)", p, stop);
    p = next;
    while (p < stop && *p != '/' && !blank(*p)) ++p;
    return resolved(value, count);
  }

  // The material is named by the rest of the line, as `newmtl` names it in the library: Max2Mtl and others write
  // names with spaces ("Hard Shiny Plastic White"), whose first word alone matched no
  // material, and the faces silently took the object's. (The loader falls back to the
  // first word, which is what tinyobjloader reads.)
  void use_material(const char* p, const char* stop) {
    const std::string name = trimmed(p, stop);
    auto it = material_index_.find(name);
    if (it == material_index_.end()) {
      it = material_index_.emplace(std::string(name), static_cast<int32_t>(out_.material_names.size())).first;
      out_.material_names.emplace_back(name);
    }
    material_ = it->second;
  }

  static std::string trimmed(const char* p, const char* stop) {
    p = skip_blanks(p, stop);
    while (stop > p && blank(stop[-1])) --stop;
    return {p, stop};
  }

  std::string_view text_;
  const std::string& file_name_;
  size_t line_ = 0;
  std::string continued_;  // the lines so far of one ending in a backslash
  int32_t material_ = -1;
  std::map<std::string, int32_t, std::less<>> material_index_;
  ObjGeometry out_;
};

}  // namespace

ObjGeometry parse_obj(std::string_view text, const std::string& file_name) {
  // A byte order mark had hidden the first line's keyword (a first vertex lost shifted
  // every index after it); UTF-16 text is not OBJ as the parser reads it, and is said to
  // be so rather than "no triangles".
  text = without_byte_order_mark(text);
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF"))
    throw InputError(file_name + ": the file is UTF-16 text; save it as UTF-8 (or ASCII) to read it");
  return Parser(text, file_name).parse();
}

}  // namespace skylit
