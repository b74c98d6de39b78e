// Internal to io/: one decoder per readable format (image_reader.h's read_image picks
// one by extension), each turning a file into absolute XYZ or throwing InputError
// naming the path.
#pragma once

#include <filesystem>
#include <string>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// OpenEXR: channels R, G, B (and Y if present) or Y alone, any pixel type.
XyzImage decode_exr(const std::filesystem::path& path);
// Portable Float Map: "PF" (RGB) or "Pf" (grey), either byte order, rows bottom to top.
XyzImage decode_pfm(const std::string& bytes, const std::filesystem::path& path);

}  // namespace skylit
