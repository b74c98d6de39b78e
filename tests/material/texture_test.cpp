// Texture look-ups and their filter: texel centres read back exactly, mip levels keep
// the mean, and a footprint many texels wide returns the mean of what it covers.
#include "skylit/material/texture.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/spectrum/color_space.h"

namespace skylit {
namespace {

// A checkerboard of `cells` × `cells` squares of `side` texels, black and white.
Texture checkerboard(int cells, int side, TextureEncoding encoding) {
  const int n = cells * side;
  std::vector<uint8_t> rgba(static_cast<size_t>(n) * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const uint8_t v = ((x / side + y / side) % 2) ? 255 : 0;
      uint8_t* p = &rgba[(static_cast<size_t>(y) * n + x) * 4];
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  return Texture(n, n, std::move(rgba), encoding);
}

TEST(Texture, TexelCentresReadBackAndDecodeSrgb) {
  // 2 × 1: a texel of sRGB 188 (linear srgb_decode(188/255)) and one of 0.
  const Texture t(2, 1, {188, 20, 0, 255, 0, 0, 0, 128}, TextureEncoding::srgb);
  const Rgba left = t.bilinear(0, 0.25, 0.5);
  EXPECT_NEAR(left[0], srgb_decode(188 / 255.0), 1e-6);
  EXPECT_NEAR(left[1], srgb_decode(20 / 255.0), 1e-6);
  EXPECT_NEAR(left[3], 1.0, 1e-6);
  const Rgba right = t.bilinear(0, 0.75, 0.5);
  EXPECT_NEAR(right[0], 0.0, 1e-6);
  EXPECT_NEAR(right[3], 128 / 255.0, 1e-6);
  // Half way between the centres, the mean; repeated beyond 1.
  EXPECT_NEAR(t.bilinear(0, 0.5, 0.5)[0], 0.5 * srgb_decode(188 / 255.0), 1e-6);
  EXPECT_NEAR(t.bilinear(0, 1.25, -3.5)[0], left[0], 1e-6);
  // Linear data is not decoded.
  const Texture data(1, 1, {128, 0, 0, 255}, TextureEncoding::linear);
  EXPECT_NEAR(data.bilinear(0, 0.3, 0.3)[0], 128 / 255.0, 1e-6);
}

// Outside [0, 1): repeated, the edge stretched on, or mirrored at each whole number,
// each axis as set. A 2 × 1 texture, left texel 1 and right 0 (linear data).
TEST(Texture, WrapModesOutsideTheImage) {
  const Texture repeated(2, 1, {255, 0, 0, 255, 0, 0, 0, 255}, TextureEncoding::linear);
  const Texture clamped = repeated.with_wrap(TextureWrap::clamp_to_edge, TextureWrap::repeat);
  const Texture mirrored = repeated.with_wrap(TextureWrap::mirrored_repeat, TextureWrap::repeat);
  struct Case {
    double u;
    float repeat, clamp, mirror;
  };
  // Left texel centre at u 0.25, right at 0.75.
  for (const Case& c : {Case{1.25, 1, 0, 0}, Case{1.75, 0, 0, 1}, Case{-0.25, 0, 1, 1}, Case{-1.25, 0, 1, 0},
                        Case{2.25, 1, 0, 1}, Case{0.25, 1, 1, 1}}) {
    SCOPED_TRACE(c.u);
    EXPECT_NEAR(repeated.bilinear(0, c.u, 0.5)[0], c.repeat, 1e-6);
    EXPECT_NEAR(clamped.bilinear(0, c.u, 0.5)[0], c.clamp, 1e-6);
    EXPECT_NEAR(mirrored.bilinear(0, c.u, 0.5)[0], c.mirror, 1e-6);
  }
  // At a fold the neighbour is the edge texel itself: u = 1 reads the right texel alone.
  EXPECT_NEAR(mirrored.bilinear(0, 1.0, 0.5)[0], 0, 1e-6);
  EXPECT_NEAR(clamped.bilinear(0, 1e6, 0.5)[0], 0, 1e-6);
  // The other axis keeps its own mode, and the mean is the image's.
  EXPECT_EQ(clamped.wrap_v(), TextureWrap::repeat);
  EXPECT_NEAR(clamped.mean()[0], 0.5, 1e-2);
}

TEST(Texture, MipLevelsKeepTheMean) {
  // Black and white average to linear 0.5 (sRGB 188 after rounding, decoded 0.5029): the
  // last level's mean within one 8-bit step of it.
  const Texture t = checkerboard(8, 4, TextureEncoding::srgb);
  EXPECT_EQ(t.levels(), 6);  // 32, 16, 8, 4, 2, 1
  EXPECT_NEAR(t.mean()[0], 0.5, 0.004);
  // Level 2 (8 × 8 texels) is the checkerboard's 8 × 8 squares themselves, exactly.
  EXPECT_NEAR(t.texel(2, 0, 0)[0], 0.0, 1e-6);
  EXPECT_NEAR(t.texel(2, 1, 0)[0], 1.0, 1e-6);
}

TEST(Texture, AWideFootprintIsTheMeanOfWhatItCovers) {
  const Texture t = checkerboard(16, 4, TextureEncoding::linear);  // 64 texels, squares of 4
  // A footprint of one texel: a square's own colour.
  const double texel = 1.0 / 64;
  EXPECT_NEAR(t.filtered(2 * texel, 2 * texel, texel, 0, 0, texel)[0], 0.0, 1e-6);
  EXPECT_NEAR(t.filtered(6 * texel, 2 * texel, texel, 0, 0, texel)[0], 1.0, 1e-6);
  // 16 texels square: 4 × 4 squares, mean 0.5 wherever it lies (within the linear
  // encoding's 8-bit step, 0.002).
  for (double u : {0.1, 0.37, 0.81}) EXPECT_NEAR(t.filtered(u, 0.4, 16 * texel, 0, 0, 16 * texel)[0], 0.5, 0.01) << u;
  // Long and thin (a grazing view): 32 texels along u, one across; 8 look-ups along u
  // each 4 texels wide cover 8 squares, half of them white.
  for (double v : {0.1, 0.52}) EXPECT_NEAR(t.filtered(0.3, v, 32 * texel, 0, 0, texel)[0], 0.5, 0.06) << v;
  // Non-finite coordinates or footprints give the mean, not NaN.
  EXPECT_NEAR(t.filtered(std::nan(""), 0.1, texel, 0, 0, texel)[0], t.bilinear(0, 0, 0)[0], 1e-6);
  EXPECT_NEAR(t.filtered(0.1, 0.1, INFINITY, 0, 0, texel)[0], t.mean()[0], 1e-6);
}

}  // namespace
}  // namespace skylit
