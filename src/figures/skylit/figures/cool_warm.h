// Moreland's "cool-warm" diverging colour map: blue through a neutral light grey to
// red, with lightness symmetric about the middle, so that "more" and "less" look
// equally strong and the neutral middle stands out (for ratio maps: ratio_map.h).
// K. Moreland, "Diverging Color Maps for Scientific Visualization", Advances in Visual
// Computing (ISVC 2009), LNCS 5876, pp. 92–103; the 33-entry 8-bit table is the one he
// publishes at https://www.kennethmoreland.com/color-maps/ (CoolWarmUChar33.csv).
#pragma once

#include "skylit/figures/raster.h"

namespace skylit {

// t in [0, 1] (clamped; NaN gives the middle): 0 blue (59, 76, 192), 0.5 the neutral
// grey (221, 221, 221), 1 red (180, 4, 38); linear in sRGB code values between the
// table's entries, which lie 1/32 apart (close enough that the path between them bends
// no visible amount).
Rgb8 cool_warm(double t);

inline constexpr Rgb8 kCoolWarmBlue{59, 76, 192};
inline constexpr Rgb8 kCoolWarmNeutral{221, 221, 221};
inline constexpr Rgb8 kCoolWarmRed{180, 4, 38};

}  // namespace skylit
