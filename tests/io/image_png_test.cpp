// PNG output read back with libpng (simplified read API) and its chunks listed by hand:
// automatic exposure puts a uniform grey at sRGB 118 (0.18 encoded), a given EV maps
// luminance by 1/(1.2·2^EV) and the documented curve, and the file is deterministic.
#include <gtest/gtest.h>
#include <png.h>

#include "png_read_util.h"

#include <cmath>
#include <string>

#include "image_test_util.h"
#include "skylit/io/image/image.h"

namespace skylit {
namespace {

using Png = Raster;
Png read_png(const std::filesystem::path& path) { return test::read_png_raster(path); }

// Chunk types in file order (PNG spec §5.3: length, type, data, CRC).
std::vector<std::string> chunk_types(const std::vector<uint8_t>& bytes) {
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 8 <= bytes.size();) {
    const uint32_t length = uint32_t(bytes[at]) << 24 | bytes[at + 1] << 16 | bytes[at + 2] << 8 | bytes[at + 3];
    types.emplace_back(bytes.begin() + at + 4, bytes.begin() + at + 8);
    at += 12 + length;
  }
  return types;
}

// The documented display transform for a neutral pixel, written out independently of
// the library: exposure, the knee-and-exponential-shoulder curve, sRGB, 8 bits.
double expected_code_value(double luminance, double ev) {
  const double v = luminance / (1.2 * std::exp2(ev));
  const double knee = 0.5;
  const double d = v <= knee ? v : knee + (1 - knee) * (1 - std::exp(-(v - knee) / (1 - knee)));
  const double encoded = d <= 0.0031308 ? 12.92 * d : 1.055 * std::pow(d, 1 / 2.4) - 0.055;
  return 255 * encoded;
}

TEST(ImagePng, MidGreyAtAutomaticExposureIsSrgb118) {
  test::ScratchFolder dir("png-auto");
  // Whatever the absolute level (night street to sunlit snow), a uniform grey is the
  // log-average and is exposed to the key 0.18, whose sRGB code value is 117.7.
  for (double luminance : {0.5, 100.0, 3.0e4, 1.0e7}) {
    write_image(test::grey_image(6, 4, luminance), dir / "grey.png");
    const Png png = read_png(dir / "grey.png");
    ASSERT_EQ(png.width, 6);
    ASSERT_EQ(png.height, 4);
    for (uint8_t v : png.rgb) ASSERT_EQ(v, 118) << luminance << " cd/m²";
  }
}

TEST(ImagePng, GivenExposureFollowsTheFormula) {
  test::ScratchFolder dir("png-ev");
  const double ev = 10;  // L_max = 1.2 · 2^10 = 1228.8 cd/m²
  // Exposed values from deep shadow through the knee (0.5) to far into the shoulder.
  const std::vector<double> exposed{0.001, 0.05, 0.18, 0.25, 0.5, 0.75, 1.0, 2.0, 4.0};
  XyzImage image(int(exposed.size()), 1);
  for (int x = 0; x < image.width; ++x) {
    const double l = exposed[x] * 1228.8;
    image.set(x, 0, xyz_from_linear_srgb({l, l, l}));
  }
  write_image(image, dir / "ev.png", DisplayOptions{ev});
  const Png png = read_png(dir / "ev.png");
  ASSERT_EQ(png.rgb.size(), 3 * exposed.size());
  for (int x = 0; x < image.width; ++x) {
    const double expected = expected_code_value(exposed[x] * 1228.8, ev);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(png.rgb[3 * x + c], expected, 0.51) << "exposed " << exposed[x];
  }
  EXPECT_EQ(png.rgb[3 * 2], 118);  // 0.18 below the knee is untouched by the curve
  EXPECT_LT(png.rgb[3 * 7], 255);  // twice saturation is still below white...
  EXPECT_EQ(png.rgb[3 * 8], 255);  // ...four times is white
}

TEST(ImagePng, BytesAreDisplaySrgb8WithSrgbChunkAndNoTimestamp) {
  test::ScratchFolder dir("png-chunks");
  const XyzImage image = test::image_from_srgb({{10, 20, 30}, {300, 200, 100}, {5, 5, 5}, {1e5, 1e5, 1e5}});
  write_image(image, dir / "a.png");
  write_image(image, dir / "b.png");
  const std::vector<uint8_t> a = test::read_bytes(dir / "a.png"), b = test::read_bytes(dir / "b.png");
  EXPECT_EQ(a, b);
  const std::vector<std::string> types = chunk_types(a);
  ASSERT_FALSE(types.empty());
  EXPECT_EQ(types.front(), "IHDR");
  EXPECT_EQ(types.back(), "IEND");
  EXPECT_NE(std::find(types.begin(), types.end(), "sRGB"), types.end());
  EXPECT_EQ(std::find(types.begin(), types.end(), "tIME"), types.end());
  EXPECT_EQ(read_png(dir / "a.png").rgb, display_srgb8(image, {}));
}

TEST(ImagePng, BrightSaturatedColourDesaturatesWithoutHueShift) {
  // Pure sRGB red far above saturation: a per-channel clip would leave (255, 0, 0) with
  // the wrong luminance; desaturating toward its grey raises G and B together instead.
  const XyzImage image = test::image_from_srgb({{8000, 0, 0}});
  const std::vector<uint8_t> rgb = display_srgb8(image, DisplayOptions{10});
  EXPECT_EQ(rgb[0], 255);
  EXPECT_GT(rgb[1], 0);
  EXPECT_EQ(rgb[1], rgb[2]);
  EXPECT_LT(rgb[1], rgb[0]);
}

}  // namespace
}  // namespace skylit
