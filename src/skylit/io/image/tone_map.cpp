// The display transform (tone_map.h; docs/images.md defines each step), the log-average
// luminance it meters with, and display_srgb8 which applies it to a whole image.
#include "skylit/io/image/tone_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "skylit/core/error.h"
#include "skylit/io/image/exposure_meter.h"
#include "skylit/io/image/image_encoders.h"

namespace skylit {

// L_max = 1.2 · 2^EV: with ISO 12232's saturation speed S = 78 / H_sat and the lens
// equation H = q L t / N² (q = 0.65), L_sat = 78 / (q S) · N²/t = 1.2 · 2^EV at S = 100.
double exposure_scale(double exposure_ev) { return 1.0 / (1.2 * std::exp2(exposure_ev)); }

double exposure_ev_for_metered(double metered_luminance) { return std::log2(metered_luminance / (1.2 * kExposureKey)); }

double automatic_exposure_ev(const XyzImage& image) { return exposure_ev_for_metered(metered_luminance(image)); }

double tone_curve(double l) {
  if (!(l > 0)) return 0;
  if (l <= kToneKnee) return l;
  const double headroom = 1 - kToneKnee;
  return kToneKnee + headroom * (1 - std::exp(-(l - kToneKnee) / headroom));
}

Rgb display_linear_srgb(const Xyz& exposed) {
  const double y = exposed.y;
  if (!(y > 0)) return {0, 0, 0};
  if (!std::isfinite(y)) return {1, 1, 1};  // only with an absurd exposure: white, as film
  const double yd = tone_curve(y);
  Rgb rgb = linear_srgb_from_xyz(exposed);
  for (double& c : rgb) c *= yd / y;  // scaling all three keeps the chromaticity
  return desaturate_into_gamut(rgb, yd);
}

Rgb desaturate_into_gamut(Rgb rgb, double yd) {
  // Move toward the grey of equal luminance (yd, yd, yd), which lies inside the gamut
  // because yd < 1, just far enough to bring every channel into [0, 1]. Luminance is
  // linear in RGB, so it stays yd; and the move is along a line through the white
  // point, so the hue (dominant wavelength) stays too: only saturation is given up.
  double t = 1;
  for (double c : rgb) {
    if (!std::isfinite(c)) return {yd, yd, yd};
    if (c > 1) t = std::min(t, (1 - yd) / (c - yd));
    if (c < 0) t = std::min(t, yd / (yd - c));
  }
  for (double& c : rgb) c = std::clamp(yd + t * (c - yd), 0.0, 1.0);  // clamp: rounding only
  return rgb;
}

std::vector<uint8_t> display_srgb8(const XyzImage& image, const DisplayOptions& options) {
  check_image_shape(image);
  const double ev = options.exposure_ev ? *options.exposure_ev : automatic_exposure_ev(image);
  if (!std::isfinite(ev))
    throw InputError("display exposure_ev must be a finite number of stops, got " + std::to_string(ev));
  const double scale = exposure_scale(ev);
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  std::vector<uint8_t> out(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Xyz p = finite_pixel_or_black(image, i);
    const Rgb rgb = display_linear_srgb({p.x * scale, p.y * scale, p.z * scale});
    for (int c = 0; c < 3; ++c) out[3 * i + c] = static_cast<uint8_t>(std::lround(255.0 * srgb_encode(rgb[c])));
  }
  return out;
}

}  // namespace skylit
