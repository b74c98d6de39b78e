// The XYZ→RGB matrices are built from primaries; check them against the matrix that
// IEC 61966-2-1 publishes for sRGB, and that both spaces keep luminance in their Y row.
#include "skylit/spectrum/color_space.h"

#include <gtest/gtest.h>

namespace skylit {
namespace {

TEST(ColorSpace, SrgbMatrixMatchesIec61966) {
  // IEC 61966-2-1 (4-digit) XYZ → linear sRGB matrix; 4-digit rounding bounds the error.
  const Matrix3 published{{{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}}};
  const Matrix3 m = rgb_from_xyz_matrix(kSrgbPrimaries);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[r][c], published[r][c], 6e-4) << r << "," << c;
}

TEST(ColorSpace, YRowGivesLuminance) {
  // The Y row of rgb→xyz must be the luminance weights: 0.2126, 0.7152, 0.0722 for sRGB
  // (ITU-R BT.709) and 0.265, 0.670, 0.065 for Radiance (ray/src/common/color.h).
  const Matrix3 srgb = inverse(rgb_from_xyz_matrix(kSrgbPrimaries));
  EXPECT_NEAR(srgb[1][0], 0.2126, 1e-4);
  EXPECT_NEAR(srgb[1][1], 0.7152, 1e-4);
  EXPECT_NEAR(srgb[1][2], 0.0722, 1e-4);
  const Matrix3 radiance = inverse(rgb_from_xyz_matrix(kRadiancePrimaries));
  EXPECT_NEAR(radiance[1][0], 0.265, 1e-3);
  EXPECT_NEAR(radiance[1][1], 0.670, 1e-3);
  EXPECT_NEAR(radiance[1][2], 0.065, 1e-3);
}

TEST(ColorSpace, SrgbTransferRoundTrips) {
  for (double v : {0.0, 0.001, 0.0031308, 0.04, 0.2, 0.5, 1.0}) EXPECT_NEAR(srgb_decode(srgb_encode(v)), v, 1e-12);
  EXPECT_NEAR(srgb_encode(0.18), 0.4613561, 1e-6);  // mid grey encodes to 118/255
}

}  // namespace
}  // namespace skylit
