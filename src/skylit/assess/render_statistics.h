// Numbers for assessing a render (docs/statistics.md): the luminance of each named
// object and each material (pixel count, mean, min, max, 5th/50th/95th percentiles,
// over the pixels whose centre sees it), of the sky, of the scene's probes, the
// illuminance on the surfaces seen when the layers hold it, and for a
// fisheye view of 180° or more the daylight glare probability (glare.h). Written by
// `skylit render -o stats.json` (or .csv).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "skylit/assess/glare.h"
#include "skylit/render/pixel_layers.h"
#include "skylit/scene/scene.h"

namespace skylit {

// A photometric quantity over a set of pixels: luminance (cd/m²) or illuminance (lx).
struct LuminanceSummary {
  std::size_t pixels = 0;
  double mean = 0, min = 0, max = 0, p5 = 0, p50 = 0, p95 = 0;  // 0 without pixels
};

struct NamedSummary {
  std::string name;
  LuminanceSummary luminance;
  // On the surfaces seen (pixels of the sky left out), when the layers hold it.
  std::optional<LuminanceSummary> illuminance_lx{};
};

struct RenderStatistics {
  std::vector<NamedSummary> objects;    // every object seen, in the scene's order
  std::vector<NamedSummary> materials;  // every material seen
  LuminanceSummary sky;                 // pixels that meet no object
  std::vector<NamedSummary> probes;     // the scene's probes
  std::optional<GlareResult> glare;     // fisheye views of ≥ 180° only
};

// Percentiles by the nearest rank. InputError if a probe lies outside the image.
RenderStatistics render_statistics(const XyzImage& image, const PixelLayers& layers, const Scene& scene);

// The statistics as JSON (an object with "objects", "materials", "sky", "probes",
// "glare") or as CSV (one row per object, material, sky and probe; glare as rows too).
std::string statistics_json(const RenderStatistics& stats);
std::string statistics_csv(const RenderStatistics& stats);

// A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csv_field(const std::string& s);

}  // namespace skylit
