// The display transform's parts against their definitions in docs/images.md: the
// saturation-based exposure, the tone curve's shape,
// and gamut mapping that keeps luminance and hue.
#include "skylit/io/image/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image_test_util.h"
#include "skylit/core/error.h"

namespace skylit {
namespace {

TEST(ImageToneMap, ExposureIsSaturationBasedIso100) {
  // L_max = 1.2 · 2^EV cd/m² maps to 1.
  EXPECT_DOUBLE_EQ(exposure_scale(0), 1 / 1.2);
  EXPECT_DOUBLE_EQ(exposure_scale(10) * 1.2 * 1024, 1.0);
  EXPECT_DOUBLE_EQ(exposure_scale(-3) * 1.2 / 8, 1.0);
}

TEST(ImageToneMap, CurveIsIdentityToTheKneeThenASmoothShoulderBelowOne) {
  EXPECT_EQ(tone_curve(-1), 0);
  EXPECT_EQ(tone_curve(0), 0);
  EXPECT_EQ(tone_curve(0.18), 0.18);
  EXPECT_EQ(tone_curve(kToneKnee), kToneKnee);
  // Slope 1 on both sides of the knee: no kink that would show as a band.
  const double h = 1e-6;
  EXPECT_NEAR((tone_curve(kToneKnee + h) - tone_curve(kToneKnee)) / h, 1.0, 1e-5);
  // The shoulder as documented, rising strictly toward 1.
  EXPECT_NEAR(tone_curve(1.0), 0.5 + 0.5 * (1 - std::exp(-1.0)), 1e-15);
  double previous = tone_curve(kToneKnee);
  for (double l = 0.6; l < 8; l += 0.1) {
    EXPECT_GT(tone_curve(l), previous) << l;
    EXPECT_LT(tone_curve(l), 1.0) << l;
    previous = tone_curve(l);
  }
  EXPECT_EQ(tone_curve(1e6), 1.0);
}

// Luminance of display linear sRGB (Rec. 709 weights of the exact sRGB matrix).
double luminance(const Rgb& rgb) { return xyz_from_linear_srgb(rgb).y; }

TEST(ImageToneMap, OutOfGamutColoursDesaturateTowardTheirOwnLuminance) {
  // Outside sRGB (negative R, like a low-pressure sodium or a laser-pure green) and
  // too bright for the display (components above 1 after the curve).
  for (const Rgb& input : {Rgb{-0.1, 0.3, 0.05}, Rgb{2.5, 0.2, 0.1}, Rgb{-0.3, 1.8, -0.05}}) {
    const Xyz xyz = xyz_from_linear_srgb(input);
    const Rgb out = display_linear_srgb(xyz);
    const double yd = tone_curve(xyz.y);
    for (double c : out) {
      EXPECT_GE(c, 0.0);
      EXPECT_LE(c, 1.0);
    }
    EXPECT_NEAR(luminance(out), yd, 1e-9);  // luminance kept exactly
    // Hue kept: out − grey is parallel to input − grey.
    const Rgb a{input[0] - xyz.y, input[1] - xyz.y, input[2] - xyz.y};
    const Rgb b{out[0] - yd, out[1] - yd, out[2] - yd};
    EXPECT_NEAR(a[0] * b[1] - a[1] * b[0], 0, 1e-9);
    EXPECT_NEAR(a[1] * b[2] - a[2] * b[1], 0, 1e-9);
    EXPECT_GT(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], 0);  // same direction, not flipped
  }
}

TEST(ImageToneMap, InGamutColoursBelowTheKneeAreUntouched) {
  const Rgb input{0.2, 0.1, 0.05};
  const Rgb out = display_linear_srgb(xyz_from_linear_srgb(input));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c], input[c], 1e-12);
}

TEST(ImageToneMap, NonFiniteExposureIsAnInputError) {
  EXPECT_THROW(display_srgb8(test::grey_image(2, 2, 1), DisplayOptions{NAN}), InputError);
}

}  // namespace
}  // namespace skylit
