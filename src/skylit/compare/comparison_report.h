// The results of `skylit compare` for people (an aligned table) and for programs (JSON);
// docs/validation.md describes both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "skylit/compare/region_comparison.h"

namespace skylit {

// What was compared, as the user named it.
struct ComparedFiles {
  std::string a, b;
  std::optional<std::string> standard_error_a, standard_error_b;
  int width = 0, height = 0;
};

// A heading naming the files, then one row per region: pixels, dark pixels, mean
// luminances (cd/m²), B/A and its standard error, and the per-pixel ratio's median,
// 5th and 95th percentiles. Columns are aligned by characters (UTF-8 aware); a value
// that does not exist (no standard-error image, no lit pixel) is "-".
std::string comparison_table(const ComparedFiles& files, const std::vector<RegionComparison>& regions);

// One JSON object: the files, the size, and "regions": [...] with the same numbers under
// names that carry their units; a value that does not exist is null. Ends with a newline.
std::string comparison_json(const ComparedFiles& files, const std::vector<RegionComparison>& regions);

}  // namespace skylit
