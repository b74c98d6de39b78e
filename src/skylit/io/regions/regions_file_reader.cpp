// read_regions_file (regions_reader.h): checked JSON through JsonReader, so every
// mistake is reported with the file and the JSON path, as in scene files.
#include <cmath>
#include <set>
#include <string>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/io/regions/regions_reader.h"
#include "skylit/io/scene/json_reader.h"

namespace skylit {
namespace {

std::string rectangle_text(double x0, double y0, double x1, double y1) {
  char text[128];
  std::snprintf(text, sizeof text, "[%g, %g, %g, %g]", x0, y0, x1, y1);
  return text;
}

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// "rect": four integers, inside the image, not empty.
ImageRegion pixel_rectangle(const JsonReader& rect, const std::string& name, int width, int height) {
  if (!rect.is_array() || rect.raw().size() != 4) rect.fail_expected("an array of 4 integers [x0, y0, x1, y1]");
  const auto e = rect.elements();
  const int limit = 1 << 30;
  const int x0 = e[0].integer_in(-limit, limit), y0 = e[1].integer_in(-limit, limit);
  const int x1 = e[2].integer_in(-limit, limit), y1 = e[3].integer_in(-limit, limit);
  if (x0 >= x1 || y0 >= y1)
    rect.fail(rectangle_text(x0, y0, x1, y1) + " is empty; expected x0 < x1 and y0 < y1 (half-open pixel ranges)");
  if (x0 < 0 || y0 < 0 || x1 > width || y1 > height)
    rect.fail(rectangle_text(x0, y0, x1, y1) + " reaches outside the " + size_text(width, height) +
              " images (x0, x1 from 0 to " + std::to_string(width) + ", y0, y1 from 0 to " + std::to_string(height) +
              ")");
  return rectangle_region(name, width, x0, y0, x1, y1);
}

// "rect_fraction": four numbers in [0, 1]; pixel i is inside when its centre
// (i + 0.5) / size lies in [f0, f1), i.e. ceil(f0 · size − 0.5) ≤ i < ceil(f1 · size − 0.5).
ImageRegion fraction_rectangle(const JsonReader& rect, const std::string& name, int width, int height) {
  if (!rect.is_array() || rect.raw().size() != 4)
    rect.fail_expected("an array of 4 fractions [x0, y0, x1, y1] of the width and height");
  const auto e = rect.elements();
  const double f[4] = {e[0].number_in(0, 1), e[1].number_in(0, 1), e[2].number_in(0, 1), e[3].number_in(0, 1)};
  if (f[0] >= f[2] || f[1] >= f[3])
    rect.fail(rectangle_text(f[0], f[1], f[2], f[3]) + " is empty; expected x0 < x1 and y0 < y1");
  const auto first_pixel = [](double fraction, int size) { return static_cast<int>(std::ceil(fraction * size - 0.5)); };
  const int x0 = first_pixel(f[0], width), x1 = first_pixel(f[2], width);
  const int y0 = first_pixel(f[1], height), y1 = first_pixel(f[3], height);
  if (x0 >= x1 || y0 >= y1)
    rect.fail(rectangle_text(f[0], f[1], f[2], f[3]) + " holds no pixel centre of the " + size_text(width, height) +
              " images");
  return rectangle_region(name, width, x0, y0, x1, y1);
}

}  // namespace

std::vector<ImageRegion> read_regions_file(const std::filesystem::path& path, int width, int height) {
  const std::string source = path.string();
  const nlohmann::json document = parse_json_text(read_text_file(path, "regions file"), source);
  const JsonReader top(document, source);
  top.allow_only({"regions"});
  std::vector<ImageRegion> regions;
  std::set<std::string> names;
  for (const JsonReader& entry : top.required("regions").elements()) {
    entry.allow_only({"name", "rect", "rect_fraction"});
    const JsonReader name_reader = entry.required("name");
    const std::string name = name_reader.string();
    if (name.empty()) name_reader.fail("expected a non-empty name");
    if (!names.insert(name).second) name_reader.fail("the name \"" + name + "\" is used twice");
    const auto rect = entry.optional("rect");
    const auto fraction = entry.optional("rect_fraction");
    if (rect.has_value() == fraction.has_value())
      entry.fail("expected exactly one of 'rect' (pixels) and 'rect_fraction' (fractions of width and height)");
    regions.push_back(rect ? pixel_rectangle(*rect, name, width, height)
                           : fraction_rectangle(*fraction, name, width, height));
  }
  if (regions.empty()) top.required("regions").fail("expected at least one region");
  return regions;
}

}  // namespace skylit
