// read_image: EXR and PFM written by write_image come back as the XYZ that went in
// (Y exactly from EXR's Y channel), PFM's other byte order and grey variant are read,
// and every bad file is one InputError naming the path.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "../test_support.h"
#include "image_test_util.h"
#include "skylit/io/image/image_reader.h"

namespace skylit {
namespace {

using test::ScratchFolder;
using testing::input_error_of;

XyzImage coloured_image() {
  XyzImage image(3, 2);
  image.set(0, 0, xyz_from_linear_srgb({1.0, 2.0, 3.0}));
  image.set(1, 0, xyz_from_linear_srgb({1e5, 2e4, 3e3}));
  image.set(2, 0, xyz_from_linear_srgb({0.0, 0.0, 0.0}));
  image.set(0, 1, xyz_from_linear_srgb({0.001, 0.002, 0.0005}));
  image.set(1, 1, xyz_from_linear_srgb({-0.1, 0.5, 0.2}));  // outside sRGB: kept
  image.set(2, 1, xyz_from_linear_srgb({7.0, 7.0, 7.0}));
  return image;
}

void expect_same(const XyzImage& read, const XyzImage& written) {
  ASSERT_EQ(read.width, written.width);
  ASSERT_EQ(read.height, written.height);
  for (int y = 0; y < written.height; ++y)
    for (int x = 0; x < written.width; ++x) {
      const Xyz r = read.at(x, y), w = written.at(x, y);
      const double scale = std::abs(w.x) + std::abs(w.y) + std::abs(w.z) + 1e-30;
      EXPECT_NEAR(r.x, w.x, 1e-6 * scale) << x << "," << y;
      EXPECT_NEAR(r.y, w.y, 1e-6 * scale) << x << "," << y;
      EXPECT_NEAR(r.z, w.z, 1e-6 * scale) << x << "," << y;
    }
}

TEST(ImageReader, ExrAndPfmComeBackAsWritten) {
  ScratchFolder dir("reader_round_trip");
  const XyzImage image = coloured_image();
  for (const char* name : {"a.exr", "a.pfm", "A.EXR"}) {
    write_image(image, dir / name);
    expect_same(read_image(dir / name), image);
  }
  // EXR's Y channel is the luminance itself, float for float.
  const XyzImage exr = read_image(dir / "a.exr");
  EXPECT_EQ(exr.at(1, 0).y, static_cast<double>(static_cast<float>(image.at(1, 0).y)));
}

TEST(ImageReader, ReadsBigEndianAndGreyPfm) {
  ScratchFolder dir("reader_pfm_variants");
  // 2 × 1 grey, big-endian (positive scale): 1.5 then 4.0; rows bottom-up (one row).
  std::string grey = "Pf\n2 1\n1.0\n";
  for (const char* bytes : {"\x3f\xc0\x00\x00", "\x40\x80\x00\x00"}) grey.append(bytes, 4);
  std::ofstream(dir / "grey.pfm", std::ios::binary) << grey;
  const XyzImage image = read_image(dir / "grey.pfm");
  ASSERT_EQ(image.width, 2);
  EXPECT_NEAR(image.at(0, 0).y, 1.5, 1e-12);
  EXPECT_NEAR(image.at(1, 0).y, 4.0, 1e-12);
  // A grey is D65 white: x/y chromaticity 0.3127, 0.3290.
  const Xyz p = image.at(1, 0);
  EXPECT_NEAR(p.x / (p.x + p.y + p.z), 0.3127, 1e-4);
}

TEST(ImageReader, BadFilesAreOneLineNamingThePath) {
  ScratchFolder dir("reader_errors");
  EXPECT_EQ(input_error_of([&] { read_image(dir / "none.exr"); }),
            "cannot read \"" + (dir / "none.exr").string() + "\": no such file");
  EXPECT_NE(input_error_of([&] { read_image(dir / "a.png"); }).find("unknown extension \".png\""), std::string::npos);
  std::ofstream(dir / "junk.exr") << "not an exr";
  const std::string junk = input_error_of([&] { read_image(dir / "junk.exr"); });
  EXPECT_NE(junk.find("junk.exr\": not a readable OpenEXR file"), std::string::npos) << junk;
  std::ofstream(dir / "short.pfm", std::ios::binary) << "PF\n4 4\n-1.0\n0123";
  const std::string truncated = input_error_of([&] { read_image(dir / "short.pfm"); });
  EXPECT_NE(truncated.find("short.pfm\": truncated PFM"), std::string::npos) << truncated;
  std::ofstream(dir / "text.pfm") << "hello";
  EXPECT_NE(input_error_of([&] { read_image(dir / "text.pfm"); }).find("not a PFM file"), std::string::npos);
}

}  // namespace
}  // namespace skylit
