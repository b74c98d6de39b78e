// Daylight glare probability (DGP) of a 180° fisheye view: Wienold and Christoffersen,
// "Evaluation methods and development of a new glare prediction model for daylight
// environments with the use of CCD cameras", Energy and Buildings 38 (2006) 743–757:
//   DGP = 5.87·10⁻⁵ E_v + 9.18·10⁻² log₁₀(1 + Σ L_s² ω_s / (E_v^1.87 P_s²)) + 0.16
// with E_v the vertical illuminance at the eye (lx), and L_s (cd/m²), ω_s (sr) and P_s
// (Guth's position index) of each glare source. docs/images.md, "Glare".
#pragma once

#include "skylit/render/camera.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// The paper's method (evalglare's -b 5; its own default is now a fixed 2000 cd/m²): a
// pixel is part of a glare source when its luminance exceeds this many times the
// view's mean luminance.
inline constexpr double kGlareSourceFactor = 5.0;

struct GlareResult {
  double dgp = 0;
  double vertical_illuminance_lx = 0;  // E_v, from the half-space in front of the eye
  double mean_luminance = 0;           // over that half-space, cd/m²
  double source_solid_angle_sr = 0;    // of all glare pixels
  double source_mean_luminance = 0;    // of the glare pixels, solid-angle weighted
};

// Guth's position index for a source σ degrees off the line of sight, at τ degrees from
// the vertical plane through it (0 above, 90 to the side), as evalglare computes it:
// exp((35.2 − 0.31889τ − 1.22e^(−2τ/9))·10⁻³σ + (21 + 0.26667τ − 0.002963τ²)·10⁻⁵σ²),
// at most 16. Sources below the line of sight use the mirror image above it (τ from the
// downward vertical); evalglare uses Iwata's index there instead.
double guth_position_index(double sigma_deg, double tau_deg);

// DGP of `image` seen through `camera` (a fisheye covering the half-space in front of
// the eye: 180° or more): every pixel the camera sees within 90° of the line of sight
// adds L ω cos θ to E_v; pixels brighter than kGlareSourceFactor × the mean are glare
// sources, each pixel with its own position index. DGP is clamped to at most 1.
GlareResult daylight_glare_probability(const XyzImage& image, const ImageCamera& camera);

}  // namespace skylit
