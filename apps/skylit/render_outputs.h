// What `skylit render -o FILE` writes, chosen by the file's name: an image (.exr .pfm
// .hdr .png), a false-colour image (*.falsecolor.png), statistics (.json, .csv;
// docs/statistics.md) or the HTML report (.html; docs/report.md). The checks run before the render, so that a wrong
// name costs nothing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "skylit/io/image/image.h"
#include "skylit/render/pixel_layers.h"
#include "skylit/scene/scene.h"

namespace skylit::cli {

// InputError naming the path if its kind (extension) is not one render writes; its
// folder is checked by the OutputFiles that reserve it (io/output_files.h).
void check_render_output(const std::string& path);

// Whether any of the outputs needs the pixel layers (statistics, or EXR data layers).
bool outputs_need_layers(const std::vector<std::string>& paths, const Scene& scene);

// The bytes of one output of a finished render, for an all-or-nothing set of outputs
// (io/output_files.h); `layers` may be null when outputs_need_layers said no. The
// report's title names `scene_file`.
std::vector<uint8_t> render_output_bytes(const std::string& path, const XyzImage& image, const Scene& scene,
                                         const DisplayOptions& display, const PixelLayers* layers,
                                         const std::string& scene_file);

}  // namespace skylit::cli
