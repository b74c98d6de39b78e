// The regions `skylit compare` reports on, read from a user's files (docs/validation.md):
// a JSON list of named rectangles, or a PNG mask in which every distinct non-black
// colour is a region. Both need the images' size, so that a region reaching outside
// them is refused with the file and the place.
#pragma once

#include <filesystem>
#include <vector>

#include "skylit/compare/image_region.h"

namespace skylit {

// `{"regions": [{"name": "sunlit wall", "rect": [x0, y0, x1, y1]}, ...]}`: pixel
// rectangles, half-open ([x0, x1) × [y0, y1), from the top-left), or "rect_fraction"
// with the same four numbers as fractions of the width and height (the pixels whose
// centres fall inside), so that one file serves any resolution. InputError
// "<file>: regions[i].rect: ..." for bad JSON, a missing or unknown key, a repeated
// name, or a rectangle that is empty or reaches outside the `width` × `height` images.
std::vector<ImageRegion> read_regions_file(const std::filesystem::path& path, int width, int height);

// A PNG the images' size; each distinct colour other than black (or fully transparent)
// is a region named by its hex colour, "#rrggbb", in ascending order of that name.
// InputError naming the file for an unreadable PNG, another size, or more than
// kMaxMaskColours colours (an anti-aliased mask).
std::vector<ImageRegion> read_region_mask(const std::filesystem::path& path, int width, int height);

inline constexpr int kMaxMaskColours = 256;

}  // namespace skylit
