// The human-vision display (human_display.h).
#include "skylit/io/image/human_display.h"

#include <algorithm>
#include <cmath>

#include "skylit/io/image/human_vision_limits.h"
#include "skylit/io/image/image_encoders.h"
#include "skylit/io/image/tone_map.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {
namespace {

constexpr int kBins = 100;
// The paper's stopping rule: the ceiling has converged when less than this share of
// the samples is trimmed in a pass; when the samples left fall below it, the world's
// range fits the display and a linear mapping is used instead.
constexpr double kTolerance = 0.025;
constexpr double kLowestLuminance = 1e-5;  // cd/m²: darker counts as this (a log scale)
// D65 white's X and Z for Y = 1: the veil's colour (light scattered in the eye mixes
// the field's colours; grey is its mean for a neutral scene).
constexpr double kD65WhiteX = 0.95047, kD65WhiteZ = 1.08883;

// Ward (1994)'s contrast-based scale factor: display = world × m, so that a
// just-visible contrast at the world's adaptation stays just visible on the display.
double ward_scale(double world_adaptation) {
  const double d = kHumanDisplayMax / 2;
  return std::pow((1.219 + std::pow(d, 0.4)) / (1.219 + std::pow(world_adaptation, 0.4)), 2.5);
}

}  // namespace

double threshold_luminance(double adaptation) {
  const double l = std::log10(std::max(adaptation, 1e-12));
  double t;
  if (l < -3.94)
    t = -2.86;
  else if (l < -1.44)
    t = std::pow(0.405 * l + 1.6, 2.18) - 2.86;
  else if (l < -0.0184)
    t = l - 0.395;
  else if (l < 1.9)
    t = std::pow(0.249 * l + 0.65, 2.7) - 0.72;
  else
    t = l - 1.255;
  return std::pow(10.0, t);
}

HumanDisplayMapping::HumanDisplayMapping(const std::vector<double>& foveal) {
  std::vector<double> logs;
  for (double l : foveal)
    if (std::isfinite(l)) logs.push_back(std::log10(std::max(l, kLowestLuminance)));
  if (logs.empty()) logs.push_back(std::log10(kLowestLuminance));
  log_min_ = *std::min_element(logs.begin(), logs.end());
  log_max_ = *std::max_element(logs.begin(), logs.end());
  double log_mean = 0;
  for (double l : logs) log_mean += l / double(logs.size());
  const double display_range = std::log10(kHumanDisplayMax / kHumanDisplayMin);
  scale_ = ward_scale(std::pow(10.0, log_mean));
  if (log_max_ - log_min_ <= display_range * 1e-3) {
    linear_ = true;
    return;
  }
  const double width = (log_max_ - log_min_) / kBins;
  std::vector<double> counts(kBins, 0.0);
  for (double l : logs) counts[std::min(kBins - 1, int((l - log_min_) / width))] += 1;
  const double total0 = double(logs.size());
  // Trim every bin to its ceiling (the paper's Eq. 10) until a pass trims less than
  // kTolerance of the samples: the cumulative distribution's slope then keeps every
  // displayed contrast at or below the threshold ratio ΔL_t(L_d)/ΔL_t(L_w).
  for (int pass = 0; pass < 100; ++pass) {
    double total = 0;
    for (double c : counts) total += c;
    if (total < kTolerance * total0) {
      linear_ = true;
      return;
    }
    double trimmed = 0, below = 0;
    std::vector<double> ceiling(kBins);
    for (int i = 0; i < kBins; ++i) {
      const double log_world = log_min_ + (i + 0.5) * width;
      const double p = (below + counts[i] / 2) / total;
      below += counts[i];
      const double log_display = std::log10(kHumanDisplayMin) + display_range * p;
      const double world = std::pow(10.0, log_world), display = std::pow(10.0, log_display);
      ceiling[i] =
          threshold_luminance(display) / threshold_luminance(world) * world / display * total * width / display_range;
    }
    for (int i = 0; i < kBins; ++i)
      if (counts[i] > ceiling[i]) {
        trimmed += counts[i] - ceiling[i];
        counts[i] = ceiling[i];
      }
    if (trimmed < kTolerance * total) break;
  }
  double total = 0;
  for (double c : counts) total += c;
  cumulative_.resize(kBins);
  double sum = 0;
  for (int i = 0; i < kBins; ++i) cumulative_[i] = (sum += counts[i]) / total;
}

double HumanDisplayMapping::display_luminance(double world) const {
  if (!(world > 0)) return 0;
  if (linear_) return std::min(kHumanDisplayMax, world * scale_);
  const double width = (log_max_ - log_min_) / kBins;
  const double x = (std::log10(std::max(world, kLowestLuminance)) - log_min_) / width;  // in bins
  double p;
  if (x <= 0)
    p = 0;
  else if (x >= kBins)
    p = 1;
  else {
    // Linear within the bin between the cumulative values at its edges.
    const int i = int(x);
    const double lower = i == 0 ? 0 : cumulative_[i - 1];
    p = lower + (x - i) * (cumulative_[i] - lower);
  }
  return std::pow(10.0, std::log10(kHumanDisplayMin) + std::log10(kHumanDisplayMax / kHumanDisplayMin) * p);
}

std::vector<uint8_t> human_display_srgb8(const XyzImage& image, double degrees_per_pixel) {
  check_image_shape(image);
  const int w = image.width, h = image.height;
  // Foveal samples: box means over about 1°.
  const int k = std::max(1, int(std::lround(1.0 / std::max(degrees_per_pixel, 1e-6))));
  const int fw = (w + k - 1) / k, fh = (h + k - 1) / k;
  std::vector<double> fovea(std::size_t(fw) * fh, 0.0), counts(fovea.size(), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Xyz p = finite_pixel_or_black(image, std::size_t(y) * w + x);
      fovea[std::size_t(y / k) * fw + x / k] += std::max(0.0, p.y);
      counts[std::size_t(y / k) * fw + x / k] += 1;
    }
  for (std::size_t i = 0; i < fovea.size(); ++i) fovea[i] /= counts[i];
  // Veiling glare: the foveal samples, and every pixel, take kVeilShare of their light
  // from the veil of the rest of the field (the paper's §5.1), a grey veil.
  const std::vector<double> veil = veiling_luminance(fovea, fw, fh, k * std::max(degrees_per_pixel, 1e-6));
  for (std::size_t i = 0; i < fovea.size(); ++i) fovea[i] = (1 - kVeilShare) * fovea[i] + veil[i];
  XyzImage veiled(w, h);
  std::vector<double> adaptation(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const Xyz p = finite_pixel_or_black(image, i);
      const double v = grid_at(veil, fw, fh, k, x, y);
      veiled.set(x, y,
                 {(1 - kVeilShare) * p.x + kD65WhiteX * v, (1 - kVeilShare) * p.y + v,
                  (1 - kVeilShare) * p.z + kD65WhiteZ * v});
      adaptation[i] = grid_at(fovea, fw, fh, k, x, y);
    }
  // Acuity: detail finer than a person resolves at each place's adaptation is lost (§5.2).
  const XyzImage seen = acuity_limited(veiled, adaptation, degrees_per_pixel);
  const HumanDisplayMapping mapping(fovea);

  std::vector<uint8_t> out(3 * std::size_t(w) * h);
  const double mesopic_span = std::log10(kPhotopicAbove / kScotopicBelow);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const Xyz p = finite_pixel_or_black(seen, i);
      Rgb rgb{0, 0, 0};
      if (p.y > 0) {
        const double yd = mapping.display_luminance(p.y) / kHumanDisplayMax;  // display white = 1
        // Colour kept in proportion to how photopic the local adaptation is.
        const double colour =
            std::clamp(std::log10(std::max(adaptation[i], 1e-12) / kScotopicBelow) / mesopic_span, 0.0, 1.0);
        const double grey = std::clamp(yd, 0.0, 1.0);
        const Rgb c = desaturate_into_gamut(linear_srgb_from_xyz({p.x * grey / p.y, grey, p.z * grey / p.y}), grey);
        for (int ch = 0; ch < 3; ++ch) rgb[ch] = grey + colour * (c[ch] - grey);
      }
      for (int ch = 0; ch < 3; ++ch)
        out[3 * i + ch] = static_cast<uint8_t>(std::lround(255.0 * srgb_encode(std::clamp(rgb[ch], 0.0, 1.0))));
    }
  return out;
}

}  // namespace skylit
