// The "viridis" colour map: dark blue through green to yellow, perceptually uniform
// (equal steps of the value look like equal steps of colour, in CAM02-UCS), monotonic
// in lightness so that it reads in grey print too, and readable by people with the
// common colour-vision deficiencies. For false-colour images (false_colour.h).
// S. van der Walt and N. Smith, matplotlib 2.0 (2015), released to the public domain
// (CC0); the table is matplotlib's _viridis_data (lib/matplotlib/_cm_listed.py),
// every 8th of its 256 entries and the last, rounded to 8 bits.
#pragma once

#include "skylit/figures/raster.h"

namespace skylit {

// t in [0, 1] (clamped; NaN gives 0): 0 dark violet (68, 1, 84), 1 yellow (253, 231, 37);
// linear in sRGB code values between the table's entries.
Rgb8 viridis(double t);

}  // namespace skylit
