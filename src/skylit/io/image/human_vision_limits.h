// Two limits of human vision that the human display (human_display.h) shows, after Ward
// Larson, Rushmeier and Piatko (IEEE TVCG 3(4), 1997, §5), the method of pcond -h:
//   - veiling glare: light scattered in the eye from bright parts of the field veils
//     the rest, so a lamp at night hides what stands next to it;
//   - acuity: in dim light the finest detail a person can resolve grows coarse
//     (Shaler 1937's data), so a night scene loses its fine detail.
#pragma once

#include <vector>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// The share of a sample's adaptation that comes from the veil (the paper's and pcond's
// 0.08): the displayed luminance is 0.92 L + L_veil.
inline constexpr double kVeilShare = 0.08;

// The highest spatial frequency (cycles per degree) a person resolves at adaptation
// luminance `adaptation` (cd/m²): 17.25 atan(1.4 log₁₀ L_a + 0.35) + 25.72, the
// paper's fit to Shaler's data (about 48 in daylight, 3 at 0.001 cd/m²).
double acuity_cycles_per_degree(double adaptation);

// A grid's value at (x, y) of the finer grid it was made from (each of its cells covers
// block × block of those), bilinear between the cells' centres: for veils and
// adaptation levels, which are smooth and would otherwise show their cells.
double grid_at(const std::vector<double>& grid, int gw, int gh, int block, int x, int y);

// The veiling luminance (cd/m²) at each of fw × fh foveal samples `fovea` (cd/m², rows
// from the top) spaced `degrees_per_sample` apart: kVeilShare times the mean of the
// other samples' luminance weighted by cos θ / θ² (θ their angular distance, taken as
// the distance on the image), the glare spread function the paper takes from Holladay
// and Moon & Spencer. O(samples²): a grid of more than kMaxVeilSamples is averaged
// into coarser cells first.
inline constexpr int kMaxVeilSamples = 4096;
std::vector<double> veiling_luminance(const std::vector<double>& fovea, int fw, int fh, double degrees_per_sample);

// The image with the detail finer than the acuity at each pixel's adaptation
// (`adaptation`, cd/m² per pixel) removed: a box mean over one period of the highest
// resolvable frequency, 1 / (R · degrees_per_pixel) pixels across (a box's transfer
// function falls to zero at one cycle per box width). Where that is under 1.5 pixels
// the pixel is kept as it is.
XyzImage acuity_limited(const XyzImage& image, const std::vector<double>& adaptation, double degrees_per_pixel);

}  // namespace skylit
