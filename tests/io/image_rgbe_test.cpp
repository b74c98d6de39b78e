// Radiance .hdr output decoded here the way Radiance's own reader does it
// (ray/src/common/color.c: freadcolrs for the run-length scanlines, colr_color for
// (mantissa + 0.5)·2^(exponent − 136)), then checked in Radiance's luminance
// convention, 179 × (0.265 R + 0.670 G + 0.065 B), against the input Y.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "image_test_util.h"
#include "skylit/io/image/image.h"

namespace skylit {
namespace {

struct HdrFile {
  std::vector<std::string> header;  // lines before the blank line
  std::string resolution;
  int width = 0, height = 0;
  std::vector<std::array<uint8_t, 4>> rgbe;  // rows top to bottom
  int encoded_rows = 0;                      // rows in the run-length format
};

HdrFile decode_hdr(const std::vector<uint8_t>& bytes) {
  HdrFile out;
  std::size_t pos = 0;
  auto next = [&]() -> uint8_t {
    if (pos >= bytes.size()) throw std::runtime_error("hdr: unexpected end of file");
    return bytes[pos++];
  };
  auto line = [&] {
    std::string s;
    for (char c; (c = char(next())) != '\n';) s += c;
    return s;
  };
  for (std::string s; !(s = line()).empty();) out.header.push_back(s);
  out.resolution = line();
  if (std::sscanf(out.resolution.c_str(), "-Y %d +X %d", &out.height, &out.width) != 2)
    throw std::runtime_error("hdr: resolution line " + out.resolution);
  out.rgbe.resize(std::size_t(out.width) * out.height);
  for (int y = 0; y < out.height; ++y) {
    auto* row = &out.rgbe[std::size_t(y) * out.width];
    const bool may_encode = out.width >= 8 && out.width <= 0x7fff;
    if (may_encode && pos + 2 < bytes.size() && bytes[pos] == 2 && bytes[pos + 1] == 2 && !(bytes[pos + 2] & 0x80)) {
      ++out.encoded_rows;
      pos += 2;
      const int length = next() << 8;
      if ((length | next()) != out.width) throw std::runtime_error("hdr: scanline length");
      for (int c = 0; c < 4; ++c)
        for (int x = 0; x < out.width;) {
          int code = next();
          if (code > 128) {  // a run of code − 128 copies of the next byte
            code -= 128;
            const uint8_t v = next();
            if (x + code > out.width) throw std::runtime_error("hdr: run overflows");
            while (code--) row[x++][c] = v;
          } else {  // code literal bytes (0 would never end the scanline)
            if (code == 0 || x + code > out.width) throw std::runtime_error("hdr: bad literal");
            while (code--) row[x++][c] = next();
          }
        }
    } else {
      for (int x = 0; x < out.width; ++x)
        for (int c = 0; c < 4; ++c) row[x][c] = next();
    }
  }
  if (pos != bytes.size()) throw std::runtime_error("hdr: trailing bytes");
  return out;
}

Rgb colr_color(const std::array<uint8_t, 4>& p) {
  if (p[3] == 0) return {0, 0, 0};
  const double f = std::ldexp(1.0, int(p[3]) - (128 + 8));
  return {(p[0] + 0.5) * f, (p[1] + 0.5) * f, (p[2] + 0.5) * f};
}

double radiance_luminance(const Rgb& rgb) { return 179.0 * (0.265 * rgb[0] + 0.670 * rgb[1] + 0.065 * rgb[2]); }

// A 40 × 3 image (long enough for run-length rows) with runs and non-runs: a block of
// one grey, then assorted colours, then a luminance ramp over ten decades.
XyzImage varied_image() {
  const std::vector<Rgb> colours{{0.2, 0.4, 0.8}, {1.0, 0.8, 0.6}, {0.1, 0.3, 0.05}, {0.5, 0.5, 0.5}, {0.7, 0.6, 0.2}};
  XyzImage image(40, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      Rgb rgb{100, 100, 100};
      if (x >= 10 && x < 20) {
        rgb = colours[(x + y) % colours.size()];
        for (double& c : rgb) c *= 5000;
      } else if (x >= 20) {
        const double l = std::pow(10.0, -1 + 0.5 * (x - 20)) * (1 + y);  // 0.1 … 8e8
        rgb = {l, l, l};
      }
      image.set(x, y, xyz_from_linear_srgb(rgb));
    }
  return image;
}

TEST(ImageRgbe, HeaderFollowsRadiance) {
  test::ScratchFolder dir("hdr-header");
  write_image(varied_image(), dir / "out.hdr");
  const HdrFile hdr = decode_hdr(test::read_bytes(dir / "out.hdr"));
  ASSERT_FALSE(hdr.header.empty());
  EXPECT_EQ(hdr.header.front(), "#?RADIANCE");
  auto has = [&](const std::string& line) {
    return std::find(hdr.header.begin(), hdr.header.end(), line) != hdr.header.end();
  };
  EXPECT_TRUE(has("FORMAT=32-bit_rle_rgbe"));
  EXPECT_TRUE(has("PRIMARIES= 0.6400 0.3300 0.2900 0.6000 0.1500 0.0600 0.3333 0.3333"));
  EXPECT_TRUE(has("EXPOSURE=1"));                                                   // absolute values: nothing to undo
  for (const std::string& l : hdr.header) EXPECT_NE(l.rfind("VIEW=", 0), 0u) << l;  // none given
  EXPECT_EQ(hdr.resolution, "-Y 3 +X 40");
  EXPECT_EQ(hdr.encoded_rows, 3);
}

TEST(ImageRgbe, ViewLineCarriesTheCamera) {
  test::ScratchFolder dir("hdr-view");
  DisplayOptions options;
  options.radiance_view = "-vta -vp 0 0 1.6 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180";
  write_image(varied_image(), dir / "out.hdr", options);
  const HdrFile hdr = decode_hdr(test::read_bytes(dir / "out.hdr"));
  EXPECT_NE(std::find(hdr.header.begin(), hdr.header.end(), "VIEW= " + *options.radiance_view), hdr.header.end());
}

// Tolerance 1 %: RGBE keeps an 8-bit mantissa under a shared exponent; the largest
// component (mantissa ≥ 128) is within 0.5/128 = 0.4 %, the others have the same
// absolute error, which for these moderately saturated colours stays below 0.9 % of the
// luminance; Radiance's 3-digit weights add ≤ 0.1 %.
TEST(ImageRgbe, RadianceLuminanceIs179TimesWeightedRgb) {
  test::ScratchFolder dir("hdr-luminance");
  const XyzImage image = varied_image();
  write_image(image, dir / "out.hdr");
  const HdrFile hdr = decode_hdr(test::read_bytes(dir / "out.hdr"));
  ASSERT_EQ(hdr.width, 40);
  ASSERT_EQ(hdr.height, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double expected = image.at(x, y).y;
      const double got = radiance_luminance(colr_color(hdr.rgbe[std::size_t(y) * 40 + x]));
      EXPECT_NEAR(got, expected, 0.01 * expected) << x << "," << y;
    }
}

TEST(ImageRgbe, EqualEnergyWhiteIsNeutralInRadianceRgb) {
  // Radiance's white is equal-energy (x = y = 1/3), not D65: XYZ = (Y, Y, Y) must be
  // R = G = B there (it would be pink in sRGB primaries).
  test::ScratchFolder dir("hdr-white");
  XyzImage image(8, 1);
  // Not whole numbers of W/sr/m²: those sit exactly on a mantissa step, where the last
  // bit of the matrix product could tip one component into the next byte.
  auto radiance = [](int x) { return x + 1.37; };
  for (int x = 0; x < 8; ++x) image.set(x, 0, {179 * radiance(x), 179 * radiance(x), 179 * radiance(x)});
  write_image(image, dir / "white.hdr");
  const HdrFile hdr = decode_hdr(test::read_bytes(dir / "white.hdr"));
  for (int x = 0; x < 8; ++x) {
    const auto& p = hdr.rgbe[x];
    EXPECT_EQ(p[0], p[1]) << x;
    EXPECT_EQ(p[1], p[2]) << x;
    EXPECT_NEAR(colr_color(p)[0], radiance(x), 0.004 * radiance(x)) << x;  // 179 cd/m² ↔ 1 W/sr/m²
  }
}

TEST(ImageRgbe, ShortScanlinesAreFlatAndNegativeIsClamped) {
  test::ScratchFolder dir("hdr-flat");
  XyzImage image(4, 2);                                 // narrower than 8: flat RGBE; the first two pixels black
  image.set(2, 0, xyz_from_linear_srgb({-5, 40, 10}));  // outside both gamuts: R < 0
  image.set(3, 0, xyz_from_linear_srgb({50, 50, 50}));
  image.set(0, 1, xyz_from_linear_srgb({1, 2, 3}));
  write_image(image, dir / "flat.hdr");
  const HdrFile hdr = decode_hdr(test::read_bytes(dir / "flat.hdr"));
  EXPECT_EQ(hdr.encoded_rows, 0);
  EXPECT_EQ(hdr.rgbe[0], (std::array<uint8_t, 4>{0, 0, 0, 0}));
  EXPECT_EQ(hdr.rgbe[1], (std::array<uint8_t, 4>{0, 0, 0, 0}));
  EXPECT_EQ(hdr.rgbe[2][0], 0);  // the negative red is clamped to 0, not wrapped
  EXPECT_NEAR(radiance_luminance(colr_color(hdr.rgbe[3])), 50.0, 0.5);
  EXPECT_NEAR(radiance_luminance(colr_color(hdr.rgbe[4])), image.at(0, 1).y, 0.01 * image.at(0, 1).y);
}

TEST(ImageRgbe, UniformRowsCompressToRuns) {
  test::ScratchFolder dir("hdr-runs");
  write_image(test::grey_image(300, 2, 42.0), dir / "grey.hdr");
  const std::vector<uint8_t> bytes = test::read_bytes(dir / "grey.hdr");
  const HdrFile hdr = decode_hdr(bytes);
  EXPECT_EQ(hdr.encoded_rows, 2);
  // Per row: 4 marker bytes + 4 components × 3 runs (127 + 127 + 46) × 2 bytes = 28.
  const std::size_t header_size = bytes.size() - 2 * 28;
  const std::string resolution = "-Y 2 +X 300\n";
  EXPECT_EQ(std::string(bytes.begin() + header_size - resolution.size(), bytes.begin() + header_size), resolution);
  for (const auto& p : hdr.rgbe) EXPECT_EQ(p, hdr.rgbe[0]);
}

}  // namespace
}  // namespace skylit
