// `skylit render -o page.html` (or --report page.html): the HTML report of the render
// (figures/html_report.h, docs/report.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "skylit/io/image/image.h"
#include "skylit/render/pixel_layers.h"
#include "skylit/scene/scene.h"

namespace skylit::cli {

bool is_report_path(const std::string& path);

// The page's bytes: the display PNG and the false-colour PNG of `image`, the scene's
// conditions, the statistics of `layers`, the luminance for the read-out.
std::vector<uint8_t> report_bytes(const std::string& title, const XyzImage& image, const Scene& scene,
                                  const DisplayOptions& display, const PixelLayers& layers);

}  // namespace skylit::cli
