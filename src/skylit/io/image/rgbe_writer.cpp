// Radiance RGBE (.hdr / .pic), written in Radiance's own convention so that its tools
// (pvalue, ximage, falsecolor) report the right luminance: Radiance computes
// luminance = 179 lm/W × (0.265 R + 0.670 G + 0.065 B) in its default primaries with
// an equal-energy white (ray/src/common/color.h: WHTEFFICACY, CIE_x_r … CIE_y_w).
// So pixels are XYZ → Radiance RGB (rgb_from_xyz_matrix(kRadiancePrimaries)), / 179.
// Encoding follows ray/src/common/color.c: setcolr (shared exponent, mantissas
// truncated, so the decoder's +0.5 lands mid-interval) and fwritecolrs ("new" run-length
// encoding of each component separately, for scanlines 8 … 32767 pixels long).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "skylit/io/image/image_encoders.h"

namespace skylit {
namespace {

// Radiance's luminous efficacy of its equal-energy white, lm/W (color.h WHTEFFICACY).
constexpr double kWhiteEfficacy = 179.0;
// fwritecolrs: run-length encode only scanlines this long; shorter runs are literals.
constexpr int kMinEncodedLength = 8, kMaxEncodedLength = 0x7fff, kMinRun = 4;

using Rgbe = std::array<uint8_t, 4>;

// setcolr: negative components (outside Radiance's gamut) become 0, as Radiance does.
Rgbe rgbe_from_rgb(Rgb rgb) {
  // Exponent byte e + 128 must stay ≤ 255: values below 2^127 (~1.7e38).
  for (double& c : rgb) c = std::clamp(c, 0.0, 1e38);
  const double d = std::max({rgb[0], rgb[1], rgb[2]});
  if (d <= 1e-32) return {0, 0, 0, 0};
  int e = 0;
  const double scale = std::frexp(d, &e) * 256.0 / d;
  Rgbe out{};
  for (int c = 0; c < 3; ++c) out[c] = static_cast<uint8_t>(std::min(255.0, rgb[c] * scale));
  out[3] = static_cast<uint8_t>(e + 128);
  return out;
}

// Length of the run of equal bytes starting at v[j], counting at most `limit`.
int run_length(const std::vector<uint8_t>& v, std::size_t j, int limit) {
  int n = 1;
  while (n < limit && j + n < v.size() && v[j + n] == v[j]) ++n;
  return n;
}

// One component of one scanline: runs of ≥ kMinRun equal bytes as (128 + n, byte),
// n ≤ 127; everything else as literals (n, n bytes), n ≤ 128. Radiance's freadcolrs
// reads code > 128 as a run and code ≤ 128 as a literal count.
void put_component(Bytes& out, const std::vector<uint8_t>& v) {
  std::size_t j = 0;
  while (j < v.size()) {
    const int run = run_length(v, j, 127);
    if (run >= kMinRun) {
      out.push_back(static_cast<uint8_t>(128 + run));
      out.push_back(v[j]);
      j += run;
      continue;
    }
    std::size_t k = j + 1;  // v[j] does not start a run, so the literal has ≥ 1 byte
    while (k < v.size() && k - j < 128 && run_length(v, k, kMinRun) < kMinRun) ++k;
    out.push_back(static_cast<uint8_t>(k - j));
    out.insert(out.end(), v.begin() + j, v.begin() + k);
    j = k;
  }
}

}  // namespace

Bytes encode_rgbe(const XyzImage& image, const DisplayOptions& options) {
  const int w = image.width, h = image.height;
  const RgbPrimaries& p = kRadiancePrimaries;
  char primaries[128];
  std::snprintf(primaries, sizeof primaries, "PRIMARIES= %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f\n", p.red_x, p.red_y,
                p.green_x, p.green_y, p.blue_x, p.blue_y, p.white_x, p.white_y);
  // EXPOSURE=1: the pixel values are Radiance's absolute units as they stand, so tools
  // that undo a picture's exposure (pvalue -o, evalglare) read them unchanged.
  std::string header = std::string("#?RADIANCE\nSOFTWARE=skylit\n") + primaries + "EXPOSURE=1\n";
  if (options.radiance_view) header += "VIEW= " + *options.radiance_view + "\n";
  header += "FORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " + std::to_string(w) + "\n";
  Bytes out(header.begin(), header.end());

  const Matrix3 radiance_from_xyz = rgb_from_xyz_matrix(kRadiancePrimaries);
  const bool encoded = w >= kMinEncodedLength && w <= kMaxEncodedLength;
  std::vector<Rgbe> scanline(w);
  std::vector<uint8_t> component(w);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Xyz v = finite_pixel_or_black(image, static_cast<std::size_t>(y) * w + x);
      Rgb rgb = apply(radiance_from_xyz, {v.x, v.y, v.z});
      for (double& c : rgb) c /= kWhiteEfficacy;
      scanline[x] = rgbe_from_rgb(rgb);
    }
    // Flat RGBE outside fwritecolrs' lengths. Safe: the largest mantissa is ≥ 128, so
    // no pixel reads as the old format's repeat marker (1, 1, 1, n).
    if (!encoded) {
      for (const Rgbe& px : scanline) out.insert(out.end(), px.begin(), px.end());
      continue;
    }
    const uint8_t marker[4] = {2, 2, static_cast<uint8_t>(w >> 8), static_cast<uint8_t>(w & 0xff)};
    out.insert(out.end(), marker, marker + 4);
    for (int c = 0; c < 4; ++c) {
      for (int x = 0; x < w; ++x) component[x] = scanline[x][c];
      put_component(out, component);
    }
  }
  return out;
}

}  // namespace skylit
