// The human-vision display (render.display = "human"; docs/images.md, "Human display"):
// what a person standing in the scene would see, after Ward Larson, Rushmeier and
// Piatko, "A visibility matching tone reproduction operator for high dynamic range
// scenes", IEEE TVCG 3(4), 1997 — the method of Radiance's pcond -h, written here
// from the paper:
//   - histogram adjustment of log luminance over ~1° "foveal" samples, with the slope
//     capped so that no contrast invisible in the scene becomes visible on the display
//     (the threshold-versus-intensity function ΔL_t of the paper's Eq. 8);
//   - colour lost as vision turns mesopic and scotopic;
//   - veiling glare around bright sources and the loss of acuity in dim light
//     (human_vision_limits.h).
#pragma once

#include <cstdint>
#include <vector>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// The display pcond assumes: 100 cd/m² white, 32:1 dynamic range.
inline constexpr double kHumanDisplayMax = 100.0, kHumanDisplayMin = 100.0 / 32.0;
// Mesopic vision between these adaptation luminances (cd/m²; the paper's §4.3): colour
// fully kept above, fully lost below, in between a mix linear in log luminance.
inline constexpr double kScotopicBelow = 0.0056, kPhotopicAbove = 5.6;

// The just-noticeable luminance difference ΔL_t (cd/m²) at adaptation luminance L_a
// (cd/m²): the paper's Eq. 8 (Ferwerda et al. 1996's rod and cone data combined).
double threshold_luminance(double adaptation);

// The mapping from world luminance (cd/m²) to display luminance (cd/m²) that histogram
// adjustment with the human contrast ceiling builds from a set of foveal samples.
class HumanDisplayMapping {
 public:
  explicit HumanDisplayMapping(const std::vector<double>& foveal_luminances);
  double display_luminance(double world_luminance) const;

 private:
  double log_min_ = 0, log_max_ = 0;
  std::vector<double> cumulative_;  // P at each bin's upper edge, 0 … 1
  bool linear_ = false;             // the world's range fits the display: a scale factor
  double scale_ = 1;
};

// 8-bit sRGB of the human display, 3 per pixel, rows from the top. `degrees_per_pixel`
// sets the foveal samples' size (about 1°).
std::vector<uint8_t> human_display_srgb8(const XyzImage& image, double degrees_per_pixel);

}  // namespace skylit
