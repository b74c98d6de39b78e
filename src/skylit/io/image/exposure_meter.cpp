// The meter of exposure_meter.h: a percentile found by nth_element, then one pass.
#include "skylit/io/image/exposure_meter.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "skylit/io/image/image_encoders.h"

namespace skylit {

double metered_luminance(std::span<const float> luminances) {
  std::vector<float> values;
  values.reserve(luminances.size());
  for (float y : luminances)
    if (std::isfinite(y)) values.push_back(std::max(0.0f, y));
  if (values.empty()) return kDarkestMeteredLuminance;

  std::vector<float> sorted = values;
  const auto nth = sorted.begin() + static_cast<std::ptrdiff_t>(kMeterHighlightPercentile * double(sorted.size() - 1));
  std::nth_element(sorted.begin(), nth, sorted.end());
  const double highlight = *nth;
  if (!(highlight > 0)) return kDarkestMeteredLuminance;

  const double lowest = highlight * std::pow(10.0, -kMeterWindowDecades);
  double sum = 0;
  std::size_t count = 0;
  for (float y : values) {
    if (y < lowest) continue;
    sum += std::log(std::min<double>(y, highlight));
    ++count;
  }
  // count ≥ 1: the highlight pixel itself lies in the window.
  return std::max(kDarkestMeteredLuminance, std::exp(sum / double(count)));
}

std::vector<float> pixel_luminances(const XyzImage& image) {
  check_image_shape(image);
  std::vector<float> y(image.xyz.size() / 3);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = pixel_is_finite(image, i) ? image.xyz[3 * i + 1] : NAN;
  return y;
}

double metered_luminance(const XyzImage& image) { return metered_luminance(pixel_luminances(image)); }

}  // namespace skylit
