// How two renders of one view differ over a region, in absolute luminance: the means
// of A and B (cd/m²), their ratio B/A with its standard error when the renders' per-pixel
// standard errors are known (the path integrator's --standard-error images), and the
// spread of the per-pixel ratio. docs/validation.md defines every number.
#pragma once

#include <optional>

#include "skylit/compare/image_region.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// A pixel is "dark" when both A and B are at or below this luminance: its ratio means
// nothing, so it is left out of the per-pixel ratio statistics and shown grey in the
// ratio map. Far below a lamp-lit street at 0.3–2 cd/m².
inline constexpr double kDarkLuminance_cd_m2 = 1e-4;

// B/A of one pixel's luminances: exact where both are above kDarkLuminance_cd_m2; a
// luminance at or below it (or negative) counts as kDarkLuminance_cd_m2, so the ratio
// is finite everywhere and 1 where both are dark.
double pixel_luminance_ratio(double luminance_a_cd_m2, double luminance_b_cd_m2);

// The per-pixel standard errors (their Y, cd/m²) of A and of B; an absent image means
// that render has no noise (the bands integrator), i.e. standard error 0.
struct StandardErrorImages {
  const XyzImage* a = nullptr;
  const XyzImage* b = nullptr;
  bool any() const { return a != nullptr || b != nullptr; }
};

struct RegionComparison {
  std::string name;
  long long pixels = 0;       // finite in both images; the others are left out
  long long dark_pixels = 0;  // of those, dark in both (kDarkLuminance_cd_m2)
  double mean_a_cd_m2 = 0, mean_b_cd_m2 = 0;
  // Standard errors of the means, sqrt(Σ SE²) / N (independent pixels): only with
  // standard-error images.
  std::optional<double> mean_a_standard_error_cd_m2, mean_b_standard_error_cd_m2;
  double ratio = 0;                            // mean B / mean A; NaN if mean A is 0
  std::optional<double> ratio_standard_error;  // delta method, A and B independent
  // Percentiles of pixel_luminance_ratio over the pixels that are not dark (linear
  // interpolation between order statistics); NaN if there are none.
  double pixel_ratio_median = 0, pixel_ratio_p05 = 0, pixel_ratio_p95 = 0;
};

// All images the same size (the caller checks, naming the files).
RegionComparison compare_region(const ImageRegion& region, const XyzImage& a, const XyzImage& b,
                                const StandardErrorImages& standard_errors = {});

// The p-quantile (0 ≤ p ≤ 1) of `values` with linear interpolation between order
// statistics at rank p · (n − 1) (Hyndman & Fan's type 7, NumPy's default); reorders
// `values`; NaN if empty.
double quantile(std::vector<double>& values, double p);

}  // namespace skylit
