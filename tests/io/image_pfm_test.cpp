// PFM output parsed byte by byte: the exact header, little-endian floats, R, G, B per
// pixel, and rows stored bottom to top as the format requires.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include "image_test_util.h"
#include "skylit/io/image/image.h"

namespace skylit {
namespace {

float little_endian_float(const std::vector<uint8_t>& bytes, std::size_t at) {
  uint32_t bits = 0;
  for (int i = 3; i >= 0; --i) bits = (bits << 8) | bytes[at + i];
  return std::bit_cast<float>(bits);
}

TEST(ImagePfm, HeaderLayoutAndBottomToTopRows) {
  test::ScratchFolder dir("pfm");
  // 3 × 2: the top row is dim, the bottom row bright, so a flipped file is caught.
  XyzImage image(3, 2);
  const Rgb top[3] = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
  const Rgb bottom[3] = {{100, 200, 300}, {-1, 50, 20}, {1e9, 1e9, 1e9}};
  for (int x = 0; x < 3; ++x) {
    image.set(x, 0, xyz_from_linear_srgb(top[x]));
    image.set(x, 1, xyz_from_linear_srgb(bottom[x]));
  }
  write_image(image, dir / "out.pfm");

  const std::vector<uint8_t> bytes = test::read_bytes(dir / "out.pfm");
  const std::string header = "PF\n3 2\n-1.0\n";  // colour, 3 × 2, little-endian
  ASSERT_EQ(bytes.size(), header.size() + 3 * 2 * 3 * sizeof(float));
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + header.size()), header);
  for (int stored_row = 0; stored_row < 2; ++stored_row) {
    const Rgb* expected = stored_row == 0 ? bottom : top;  // first stored row = bottom
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 3; ++c) {
        const std::size_t at = header.size() + 4 * (3 * (3 * stored_row + x) + c);
        const double scale = std::max({std::abs(expected[x][0]), std::abs(expected[x][1]), std::abs(expected[x][2])});
        EXPECT_NEAR(little_endian_float(bytes, at), expected[x][c], 2e-6 * scale)
            << "stored row " << stored_row << " x " << x << " channel " << c;
      }
  }
}

}  // namespace
}  // namespace skylit
