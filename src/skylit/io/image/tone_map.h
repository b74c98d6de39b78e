// The display transform behind PNG output and contact sheets, in four steps (defined
// exactly in docs/images.md):
//   1. exposure: a saturation-based ISO 100 camera at EV100 maps L_max = 1.2·2^EV cd/m²
//      to 1 (ISO 12232 saturation speed; Lagarde & de Rousiers, "Moving Frostbite to
//      PBR", SIGGRAPH 2014 course notes); automatic EV maps the metered luminance
//      (exposure_meter.h) to the key 0.18 (Reinhard et al., "Photographic tone reproduction", 2002);
//   2. a tone curve on luminance only, so chromaticity is kept: the identity up to a
//      knee, then an exponential shoulder that approaches 1 smoothly;
//   3. colours outside the sRGB gamut are desaturated toward the pixel's own grey,
//      which keeps luminance and hue where a per-channel clip would shift both;
//   4. sRGB encoding (IEC 61966-2-1) and rounding to 8 bits.
#pragma once

#include "skylit/io/image/image.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {

// Reinhard et al.'s "key": the exposed value the log-average luminance is mapped to.
inline constexpr double kExposureKey = 0.18;
// Exposed luminance where the shoulder starts; below it the tone curve is the identity,
// so an 18 % grey card metered by automatic exposure stays 0.18 (sRGB code value 118).
inline constexpr double kToneKnee = 0.5;

// Exposure scale in 1/(cd/m²) for EV100 `exposure_ev`: 1 / (1.2 · 2^EV).
double exposure_scale(double exposure_ev);

// The EV100 that maps a metered luminance L (cd/m²) to kExposureKey:
// log2(L / (1.2 · kExposureKey)).
double exposure_ev_for_metered(double metered_luminance);
// Automatic exposure: exposure_ev_for_metered(metered_luminance(image)), the meter of
// exposure_meter.h.
double automatic_exposure_ev(const XyzImage& image);

// The tone curve on exposed luminance L (dimensionless): 0 for L ≤ 0; L up to the knee
// k; above it k + (1 − k)(1 − exp(−(L − k)/(1 − k))), which has slope 1 at the knee
// (no visible kink) and tends to 1.
double tone_curve(double exposed_luminance);

// Exposed XYZ (absolute XYZ × exposure_scale) → display linear sRGB in [0, 1]³: steps 2
// and 3 above. Luminance Y ≤ 0 gives black.
Rgb display_linear_srgb(const Xyz& exposed);

// Step 3 alone: linear sRGB of luminance yd in [0, 1] moved toward the grey (yd, yd, yd)
// just far enough to lie in [0, 1]³.
Rgb desaturate_into_gamut(Rgb rgb, double yd);

}  // namespace skylit
