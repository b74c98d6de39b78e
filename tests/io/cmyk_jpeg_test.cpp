// CMYK and YCCK JPEGs (print catalogues' material photographs) decode to the RGB that
// browsers and Pillow show, R = (1 − C)(1 − K), whether the inks are stored as they are
// or inverted as Photoshop stores them behind its Adobe marker. The files are written here
// by libjpeg's own encoder, so their bytes do not come from the code under test.
#include <cmath>
#include <cstdio>  // jpeglib.h needs FILE
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <jpeglib.h>

#include "skylit/core/error.h"
#include "skylit/io/model/jpeg_texels.h"

namespace skylit {
namespace {

struct Inks {
  double c, m, y, k;  // shares of full ink, 0 to 1
};

// A 16 × 16 JPEG of one ink mix at quality 100, in `colour_space` (JCS_CMYK or JCS_YCCK);
// with `adobe` the inks stored inverted behind an Adobe marker, else as they are and no
// marker.
std::vector<unsigned char> cmyk_jpeg(const Inks& inks, J_COLOR_SPACE colour_space, bool adobe) {
  jpeg_compress_struct info{};
  jpeg_error_mgr errors{};
  info.err = jpeg_std_error(&errors);
  jpeg_create_compress(&info);
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = 16;
  info.image_height = 16;
  info.input_components = 4;
  info.in_color_space = JCS_CMYK;
  jpeg_set_defaults(&info);
  jpeg_set_colorspace(&info, colour_space);
  jpeg_set_quality(&info, 100, TRUE);
  info.write_Adobe_marker = adobe ? TRUE : FALSE;
  jpeg_start_compress(&info, TRUE);
  std::vector<unsigned char> row;
  for (int x = 0; x < 16; ++x)
    for (const double ink : {inks.c, inks.m, inks.y, inks.k}) {
      const double stored = adobe ? 1 - ink : ink;
      row.push_back(static_cast<unsigned char>(std::lround(255 * stored)));
    }
  for (int y = 0; y < 16; ++y) {
    JSAMPROW line = row.data();
    jpeg_write_scanlines(&info, &line, 1);
  }
  jpeg_finish_compress(&info);
  std::vector<unsigned char> bytes(buffer, buffer + size);
  jpeg_destroy_compress(&info);
  std::free(buffer);
  return bytes;
}

TEST(CmykJpeg, DecodesToTheLightTheInksLeave) {
  const Inks inks{0.2, 0.6, 0.9, 0.1};
  const double expected[3] = {255 * 0.8 * 0.9, 255 * 0.4 * 0.9, 255 * 0.1 * 0.9};  // 183.6, 91.8, 23.0
  for (const J_COLOR_SPACE space : {JCS_CMYK, JCS_YCCK})
    for (const bool adobe : {true, false}) {
      if (space == JCS_YCCK && !adobe) continue;  // YCCK is Adobe's alone
      SCOPED_TRACE(std::string(space == JCS_CMYK ? "CMYK" : "YCCK") + (adobe ? ", Adobe marker" : ", no marker"));
      const std::vector<unsigned char> bytes = cmyk_jpeg(inks, space, adobe);
      const JpegTexels texels = decode_jpeg(bytes.data(), bytes.size(), 64, "inks.jpg");
      ASSERT_EQ(texels.width, 16);
      ASSERT_EQ(texels.height, 16);
      // Quality 100 keeps a flat block to about a code value; YCCK's colour transform
      // rounds once more each way. The product itself rounds to ±0.5.
      const double tolerance = space == JCS_YCCK ? 3 : 2;
      for (size_t texel = 0; texel < 256; texel += 37) {
        for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(texels.rgba[4 * texel + c], expected[c], tolerance) << c;
        EXPECT_EQ(texels.rgba[4 * texel + 3], 255);
      }
    }
}

}  // namespace
}  // namespace skylit
