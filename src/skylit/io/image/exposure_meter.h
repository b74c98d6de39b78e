// Automatic exposure's light meter (docs/images.md, "Automatic exposure"): a key over
// the luminances that carry the scene, so that neither a dark night sky filling half
// the frame nor a few lamps or the sun can set the exposure, and a scene that is dark
// for the eye too (a moonless night without lamps) stays dark.
#pragma once

#include <span>
#include <vector>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// The brightest pixels that can set the meter's window: the 99th percentile, so that
// lamps, the sun's disc and their glare (< 1 % of a frame) cannot.
inline constexpr double kMeterHighlightPercentile = 0.99;
// The window's depth below that highlight, in decades: 10 stops, about what a print or
// a screen shows with detail. Darker pixels (a night sky behind lit streets) are left
// out of the average rather than dragging it down.
inline constexpr double kMeterWindowDecades = 3.0;
// The darkest luminance the meter will expose for, cd/m²: the lower end of mesopic
// vision (CIE 191:2010, 0.005 cd/m²). Below it a person sees little but shapes, so a
// scene that dark is shown dark rather than lifted to middle grey.
inline constexpr double kDarkestMeteredLuminance = 0.005;

// The meter on a list of luminances (cd/m²; non-finite values skipped, negative ones
// count as 0): with H the 99th percentile, the log-average of min(Y, H) over the
// pixels with Y ≥ H·10⁻³, and never below kDarkestMeteredLuminance. Nothing to meter
// (no finite value, or H = 0) meters as kDarkestMeteredLuminance.
double metered_luminance(std::span<const float> luminances);
// Each pixel's Y, NaN where any of X, Y, Z is not finite (a renderer bug must not set
// the exposure): what metered_luminance(image) meters.
std::vector<float> pixel_luminances(const XyzImage& image);
// The meter on pixel_luminances(image).
double metered_luminance(const XyzImage& image);

}  // namespace skylit
