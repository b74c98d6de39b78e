#include "skylit/spectrum/color_space.h"

#include <cmath>

namespace skylit {

Matrix3 inverse(const Matrix3& m) {
  const double a = m[0][0], b = m[0][1], c = m[0][2];
  const double d = m[1][0], e = m[1][1], f = m[1][2];
  const double g = m[2][0], h = m[2][1], i = m[2][2];
  const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  return {{{(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det},
           {(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det},
           {(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det}}};
}

Rgb apply(const Matrix3& m, const Rgb& v) {
  Rgb out{};
  for (int r = 0; r < 3; ++r) out[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
  return out;
}

Matrix3 rgb_from_xyz_matrix(const RgbPrimaries& p) {
  // Columns of xyz_from_rgb are the primaries' XYZ (with Y = 1), scaled so that
  // R = G = B = 1 gives the white point with Y = 1.
  auto xyz_of = [](double x, double y) { return Rgb{x / y, 1.0, (1.0 - x - y) / y}; };
  const Rgb r = xyz_of(p.red_x, p.red_y), g = xyz_of(p.green_x, p.green_y), b = xyz_of(p.blue_x, p.blue_y),
            w = xyz_of(p.white_x, p.white_y);
  const Matrix3 unscaled{{{r[0], g[0], b[0]}, {r[1], g[1], b[1]}, {r[2], g[2], b[2]}}};
  const Rgb s = apply(inverse(unscaled), w);
  Matrix3 xyz_from_rgb{};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) xyz_from_rgb[row][col] = unscaled[row][col] * s[col];
  return inverse(xyz_from_rgb);
}

namespace {
const Matrix3& srgb_from_xyz() {
  static const Matrix3 m = rgb_from_xyz_matrix(kSrgbPrimaries);
  return m;
}
const Matrix3& xyz_from_srgb() {
  static const Matrix3 m = inverse(srgb_from_xyz());
  return m;
}
}  // namespace

Rgb linear_srgb_from_xyz(const Xyz& xyz) { return apply(srgb_from_xyz(), {xyz.x, xyz.y, xyz.z}); }

Xyz xyz_from_linear_srgb(const Rgb& rgb) {
  const Rgb v = apply(xyz_from_srgb(), rgb);
  return {v[0], v[1], v[2]};
}

double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace skylit
