// CIE XYZ and the RGB spaces we write: linear sRGB (Rec. 709 primaries, D65 white;
// IEC 61966-2-1) for EXR, PFM and PNG, and Radiance's own RGB for .hdr files.
#pragma once

#include <array>

namespace skylit {

struct Xyz {
  double x = 0, y = 0, z = 0;
};

using Rgb = std::array<double, 3>;
using Matrix3 = std::array<std::array<double, 3>, 3>;

// Chromaticities of an RGB space's primaries and white point.
struct RgbPrimaries {
  double red_x, red_y, green_x, green_y, blue_x, blue_y, white_x, white_y;
};

// sRGB / Rec. 709: IEC 61966-2-1.
inline constexpr RgbPrimaries kSrgbPrimaries{0.640, 0.330, 0.300, 0.600, 0.150, 0.060, 0.3127, 0.3290};
// Radiance's default RGB (ray/src/common/color.h: CIE_x_r ... CIE_y_w, equal-energy white).
inline constexpr RgbPrimaries kRadiancePrimaries{0.640, 0.330, 0.290, 0.600, 0.150, 0.060, 1.0 / 3.0, 1.0 / 3.0};

// The matrix that takes XYZ to linear RGB of the given primaries, scaled so that
// the white point (Y = 1) maps to R = G = B = 1 (SMPTE RP 177 construction).
Matrix3 rgb_from_xyz_matrix(const RgbPrimaries& primaries);
Matrix3 inverse(const Matrix3& m);
Rgb apply(const Matrix3& m, const Rgb& v);

Rgb linear_srgb_from_xyz(const Xyz& xyz);
Xyz xyz_from_linear_srgb(const Rgb& rgb);

// The sRGB transfer function (IEC 61966-2-1), for values in [0, 1].
double srgb_encode(double linear);
double srgb_decode(double encoded);

}  // namespace skylit
