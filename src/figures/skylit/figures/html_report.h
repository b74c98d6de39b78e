// The HTML report of a render (docs/report.md): one self-contained page — its images
// and their false-colour twins as data: URIs, the conditions in words and numbers, the
// statistics tables, and a read-out under the mouse of each pixel's photometric values,
// decoded by the page's script from compact layers embedded in it (report_luminance.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "skylit/assess/render_statistics.h"
#include "skylit/io/scene/scene_conditions.h"

namespace skylit {

struct ReportImage {
  std::string caption;
  std::vector<uint8_t> png;  // the file's bytes; pixel (x, y) of the render is pixel (x, y) of the PNG
};

// A per-pixel quantity the read-out shows, as 16-bit logarithmic codes.
struct ReportLayer {
  std::string quantity, unit;  // "luminance", "cd/m²"
  std::vector<uint8_t> codes;  // luminance_code_bytes of the values, row by row
};

struct ReportPage {
  std::string title;
  std::vector<ConditionRow> conditions;
  std::vector<ReportImage> images;
  int width = 0, height = 0;        // the render's pixels
  std::vector<ReportLayer> layers;  // the read-out's quantities
  RenderStatistics statistics;
};

std::string html_report(const ReportPage& page);

}  // namespace skylit
