// EXR output read back through OpenEXR's Imf::InputFile: channels, FLOAT pixel type,
// absolute values, and the standard attributes that declare them absolute.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "image_test_util.h"
#include "skylit/io/image/image.h"

namespace skylit {
namespace {

struct ExrChannel {
  Imf::PixelType pixel_type;  // as stored in the file
  std::vector<float> values;  // width·height, rows top to bottom
};

struct ExrContents {
  int width = 0, height = 0;
  std::map<std::string, ExrChannel> channels;
  std::optional<Imf::Chromaticities> chromaticities;
  std::optional<float> white_luminance;
};

// Every channel of a single-part EXR as float (OpenEXR converts), plus the attributes.
ExrContents read_exr(const std::filesystem::path& path) {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i window = header.dataWindow();
  ExrContents out;
  out.width = window.max.x - window.min.x + 1;
  out.height = window.max.y - window.min.y + 1;
  Imf::FrameBuffer frame;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    ExrChannel& channel = out.channels[it.name()];
    channel.pixel_type = it.channel().type;
    channel.values.assign(std::size_t(out.width) * out.height, NAN);
    frame.insert(it.name(), Imf::Slice::Make(Imf::FLOAT, channel.values.data(), window));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  if (Imf::hasChromaticities(header)) out.chromaticities = Imf::chromaticities(header);
  if (Imf::hasWhiteLuminance(header)) out.white_luminance = Imf::whiteLuminance(header);
  return out;
}

TEST(ImageExr, WritesAbsoluteLinearSrgbAndLuminanceAsFloat) {
  test::ScratchFolder dir("exr");
  // Linear sRGB, absolute (cd/m² weights): a dim grey, a sky blue, sunlit foliage, a
  // colour outside the sRGB gamut (negative R must survive: EXR is linear), black, and
  // the sun's disc at ~1.6e9 cd/m², far above half float's 65504.
  const std::vector<Rgb> colours{{0.01, 0.01, 0.01}, {2000, 3500, 7000}, {30, 60, 12},
                                 {-5, 40, 10},       {0, 0, 0},          {1.7e9, 1.6e9, 1.4e9}};
  // 20 rows span two of ZIP's 16-line chunks, the second one partial.
  XyzImage image(int(colours.size()), 20);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double k = 1.0 + 0.1 * y;  // rows differ, so a row mix-up shows
      image.set(x, y, xyz_from_linear_srgb({colours[x][0] * k, colours[x][1] * k, colours[x][2] * k}));
    }
  write_image(image, dir / "out.exr");

  const ExrContents exr = read_exr(dir / "out.exr");
  ASSERT_EQ(exr.width, image.width);
  ASSERT_EQ(exr.height, image.height);
  ASSERT_EQ(exr.channels.size(), 4u);
  for (const char* name : {"R", "G", "B", "Y"}) {
    ASSERT_TRUE(exr.channels.count(name)) << name;
    EXPECT_EQ(exr.channels.at(name).pixel_type, Imf::FLOAT) << name;
  }
  auto value = [&](const char* name, std::size_t i) { return double(exr.channels.at(name).values[i]); };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = std::size_t(y) * image.width + x;
      const double k = 1.0 + 0.1 * y;
      const double r = value("R", i), g = value("G", i), b = value("B", i), lum = value("Y", i);
      const double scale = std::max({std::abs(r), std::abs(g), std::abs(b), 1e-30});
      // float storage and the XYZ round trip: a few parts in 10⁷ of the largest channel.
      EXPECT_NEAR(r, colours[x][0] * k, 2e-6 * scale) << x << "," << y;
      EXPECT_NEAR(g, colours[x][1] * k, 2e-6 * scale) << x << "," << y;
      EXPECT_NEAR(b, colours[x][2] * k, 2e-6 * scale) << x << "," << y;
      // Y is the input luminance as stored (float), and the Rec. 709 weights of R, G, B
      // give it back; 5e-4 covers those weights being rounded to 4 digits.
      EXPECT_EQ(lum, image.at(x, y).y) << x << "," << y;
      EXPECT_NEAR(0.2126 * r + 0.7152 * g + 0.0722 * b, lum, 5e-4 * scale + 1e-30) << x << "," << y;
    }
  EXPECT_GT(value("Y", 5), 65504.0);  // the sun, not clipped to half's range
  ASSERT_TRUE(exr.chromaticities.has_value());
  const Imf::Chromaticities& c = *exr.chromaticities;
  const std::array<float, 8> got{c.red.x, c.red.y, c.green.x, c.green.y, c.blue.x, c.blue.y, c.white.x, c.white.y};
  const std::array<float, 8> rec709{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
  for (int k = 0; k < 8; ++k) EXPECT_FLOAT_EQ(got[k], rec709[k]) << k;
  ASSERT_TRUE(exr.white_luminance.has_value());
  EXPECT_EQ(*exr.white_luminance, 1.0f);  // RGB (1, 1, 1) is 1 cd/m²: values are absolute
}

}  // namespace
}  // namespace skylit
