// Reading back the linear, absolute images skylit writes (EXR and PFM, docs/images.md)
// as absolute CIE XYZ, so that two renders can be compared in cd/m² (skylit compare).
#pragma once

#include <filesystem>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// By the extension (.exr or .pfm, any case). R, G, B are taken as linear sRGB
// primaries scaled as skylit writes them (0.2126 R + 0.7152 G + 0.0722 B = cd/m²) and
// turned into XYZ with xyz_from_linear_srgb. An EXR's Y channel, when present, is the
// luminance itself (it is exact where RGB may have been clamped to the float range);
// an EXR with only Y is read as a D65 grey. InputError naming the path for a missing
// or unreadable file, another extension, a malformed file or an EXR whose
// chromaticities are not sRGB's.
XyzImage read_image(const std::filesystem::path& path);

}  // namespace skylit
