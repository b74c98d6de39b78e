// compare_region (region_comparison.h). Sums are in double over float pixels, so that a
// region of millions of pixels loses nothing to rounding.
#include "skylit/compare/region_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace skylit {
namespace {

double luminance_at(const XyzImage& image, uint32_t index) {
  return image.xyz[3 * static_cast<std::size_t>(index) + 1];
}

bool finite_at(const XyzImage& image, uint32_t index) {
  const float* p = &image.xyz[3 * static_cast<std::size_t>(index)];
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

}  // namespace

double pixel_luminance_ratio(double luminance_a_cd_m2, double luminance_b_cd_m2) {
  return std::max(luminance_b_cd_m2, kDarkLuminance_cd_m2) / std::max(luminance_a_cd_m2, kDarkLuminance_cd_m2);
}

double quantile(std::vector<double>& values, double p) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double rank = p * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  std::nth_element(values.begin(), values.begin() + below, values.end());
  const double low = values[below];
  // After nth_element everything past `below` is ≥ low; the next order statistic is their minimum.
  const double high = above == below ? low : *std::min_element(values.begin() + below + 1, values.end());
  return low + (rank - static_cast<double>(below)) * (high - low);
}

RegionComparison compare_region(const ImageRegion& region, const XyzImage& a, const XyzImage& b,
                                const StandardErrorImages& standard_errors) {
  RegionComparison out;
  out.name = region.name;
  double sum_a = 0, sum_b = 0, variance_sum_a = 0, variance_sum_b = 0;
  std::vector<double> ratios;
  ratios.reserve(region.pixels.size());
  for (const uint32_t i : region.pixels) {
    if (!finite_at(a, i) || !finite_at(b, i)) continue;
    const double ya = luminance_at(a, i), yb = luminance_at(b, i);
    ++out.pixels;
    sum_a += ya;
    sum_b += yb;
    if (standard_errors.a) variance_sum_a += std::pow(luminance_at(*standard_errors.a, i), 2);
    if (standard_errors.b) variance_sum_b += std::pow(luminance_at(*standard_errors.b, i), 2);
    if (ya <= kDarkLuminance_cd_m2 && yb <= kDarkLuminance_cd_m2)
      ++out.dark_pixels;
    else
      ratios.push_back(pixel_luminance_ratio(ya, yb));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto n = static_cast<double>(out.pixels);
  out.mean_a_cd_m2 = out.pixels > 0 ? sum_a / n : nan;
  out.mean_b_cd_m2 = out.pixels > 0 ? sum_b / n : nan;
  out.ratio = out.mean_a_cd_m2 != 0 ? out.mean_b_cd_m2 / out.mean_a_cd_m2 : nan;
  if (standard_errors.any()) {
    const double se_a = std::sqrt(variance_sum_a) / n, se_b = std::sqrt(variance_sum_b) / n;
    out.mean_a_standard_error_cd_m2 = se_a;
    out.mean_b_standard_error_cd_m2 = se_b;
    // r = b/a: var r ≈ (∂r/∂b)² var b + (∂r/∂a)² var a = (se_b² + r² se_a²) / a².
    out.ratio_standard_error =
        std::sqrt(se_b * se_b + out.ratio * out.ratio * se_a * se_a) / std::abs(out.mean_a_cd_m2);
  }
  out.pixel_ratio_median = quantile(ratios, 0.5);
  out.pixel_ratio_p05 = quantile(ratios, 0.05);
  out.pixel_ratio_p95 = quantile(ratios, 0.95);
  return out;
}

}  // namespace skylit
