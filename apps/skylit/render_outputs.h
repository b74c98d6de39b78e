// What `skylit render -o FILE` writes, chosen by the file's name: an image (.exr .pfm
// .hdr .png), or a false-colour image (*.falsecolor.png). The checks run before the
// render, so that a wrong name costs nothing.
#pragma once

#include <string>

#include "skylit/io/image/image.h"
#include "skylit/scene/scene.h"

namespace skylit::cli {

// InputError naming the path if its kind or folder is wrong.
void check_render_output(const std::string& path);

// Writes one output of a finished render.
void write_render_output(const std::string& path, const XyzImage& image, const Scene& scene,
                         const DisplayOptions& display);

}  // namespace skylit::cli
