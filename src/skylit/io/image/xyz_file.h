// The exact image a shard of a split job hands to the merge (docs/cluster.md): absolute
// CIE XYZ as the renderer made it, 32-bit floats bit for bit, so that a merged sweep or
// animation writes the same bytes as one process. Not an interchange format: use EXR
// or PFM for that (their RGB is a conversion, not a copy).
//
// Layout: the line "skylit-xyz 1", the line "<width> <height>", then width × height
// pixels of X, Y, Z as little-endian IEEE floats, rows from the top.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

std::vector<uint8_t> encode_xyz_file(const XyzImage& image);

// InputError "cannot read "<path>": ..." for anything but a complete file of this
// layout (sizes 1 to 65536, the exact number of bytes) or a pixel that is not finite.
XyzImage decode_xyz_file(const std::string& bytes, const std::filesystem::path& path);
XyzImage read_xyz_file(const std::filesystem::path& path);

}  // namespace skylit
