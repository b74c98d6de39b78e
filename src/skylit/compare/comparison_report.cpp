// comparison_table and comparison_json (comparison_report.h).
#include "skylit/compare/comparison_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace skylit {
namespace {

std::string formatted(const char* format, double value) {
  if (!std::isfinite(value)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string formatted(const char* format, const std::optional<double>& value) {
  return value ? formatted(format, *value) : "-";
}

// Characters, not bytes: the headings hold "²" and "±".
std::size_t utf8_length(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// The first column left-aligned (names), the others right-aligned (numbers), two spaces apart.
std::string aligned(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths(rows.front().size(), 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], utf8_length(row[c]));
  std::string out;
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string padding(widths[c] - utf8_length(row[c]), ' ');
      if (c > 0) line += "  ";
      line += c == 0 ? row[c] + padding : padding + row[c];
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  return out;
}

using Json = nlohmann::ordered_json;  // keys in the order written, for people reading the file

Json number_or_null(double value) { return std::isfinite(value) ? Json(value) : Json(); }
Json number_or_null(const std::optional<double>& value) { return value ? number_or_null(*value) : Json(); }
Json string_or_null(const std::optional<std::string>& value) { return value ? Json(*value) : Json(); }

}  // namespace

std::string comparison_table(const ComparedFiles& files, const std::vector<RegionComparison>& regions) {
  std::string out =
      "A: " + files.a + (files.standard_error_a ? " (standard error " + *files.standard_error_a + ")" : "") +
      "\nB: " + files.b + (files.standard_error_b ? " (standard error " + *files.standard_error_b + ")" : "") + "\n" +
      std::to_string(files.width) + "x" + std::to_string(files.height) +
      " pixels; luminance in cd/m²; B/A = mean B / mean A; median, p5, p95 of B/A per pixel\n\n";
  std::vector<std::vector<std::string>> rows = {
      {"region", "pixels", "dark", "mean A", "mean B", "B/A", "± SE", "median", "p5", "p95"}};
  for (const RegionComparison& r : regions)
    rows.push_back({r.name, std::to_string(r.pixels), std::to_string(r.dark_pixels), formatted("%#.6g", r.mean_a_cd_m2),
                    formatted("%#.6g", r.mean_b_cd_m2), formatted("%.4f", r.ratio),
                    formatted("%.2g", r.ratio_standard_error), formatted("%.4f", r.pixel_ratio_median),
                    formatted("%.4f", r.pixel_ratio_p05), formatted("%.4f", r.pixel_ratio_p95)});
  return out + aligned(rows);
}

std::string comparison_json(const ComparedFiles& files, const std::vector<RegionComparison>& regions) {
  Json out;
  out["a"] = files.a;
  out["b"] = files.b;
  out["standard_error_a"] = string_or_null(files.standard_error_a);
  out["standard_error_b"] = string_or_null(files.standard_error_b);
  out["width"] = files.width;
  out["height"] = files.height;
  out["regions"] = Json::array();
  for (const RegionComparison& r : regions) {
    Json region;
    region["name"] = r.name;
    region["pixels"] = r.pixels;
    region["dark_pixels"] = r.dark_pixels;
    region["mean_a_cd_m2"] = number_or_null(r.mean_a_cd_m2);
    region["mean_b_cd_m2"] = number_or_null(r.mean_b_cd_m2);
    region["mean_a_standard_error_cd_m2"] = number_or_null(r.mean_a_standard_error_cd_m2);
    region["mean_b_standard_error_cd_m2"] = number_or_null(r.mean_b_standard_error_cd_m2);
    region["ratio"] = number_or_null(r.ratio);
    region["ratio_standard_error"] = number_or_null(r.ratio_standard_error);
    region["pixel_ratio_median"] = number_or_null(r.pixel_ratio_median);
    region["pixel_ratio_p05"] = number_or_null(r.pixel_ratio_p05);
    region["pixel_ratio_p95"] = number_or_null(r.pixel_ratio_p95);
    out["regions"].push_back(region);
  }
  return out.dump(2) + "\n";
}

}  // namespace skylit
