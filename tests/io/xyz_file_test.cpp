// Shards' exact XYZ images (io/image/xyz_file.h): a round trip keeps every float's bits,
// and anything but a complete file is one located error.
#include "skylit/io/image/xyz_file.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cstring>

#include "../test_support.h"

namespace skylit {
namespace {

TEST(XyzFile, RoundTripKeepsEveryBit) {
  XyzImage image(3, 2);
  const float values[] = {0.0f, 1.0f, FLT_MIN / 4, FLT_MAX, 1e-30f, 3.14159274f, 65504.0f, 0.1f, 123456.789f};
  for (std::size_t i = 0; i < image.xyz.size(); ++i) image.xyz[i] = values[i % 9] * (i % 2 ? 1.0f : 0.5f);
  const std::vector<uint8_t> bytes = encode_xyz_file(image);
  const XyzImage back = decode_xyz_file(std::string(bytes.begin(), bytes.end()), "a.xyz");
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  EXPECT_EQ(std::memcmp(back.xyz.data(), image.xyz.data(), 4 * image.xyz.size()), 0);
}

TEST(XyzFile, IncompleteOrForeignFilesAreOneLocatedError) {
  const std::vector<uint8_t> good = encode_xyz_file(XyzImage(2, 2));
  const std::string text(good.begin(), good.end());
  std::string not_finite = text;
  not_finite.replace(not_finite.size() - 4, 4, std::string("\x00\x00\xc0\x7f", 4));  // a NaN
  for (const std::string& bad : {std::string(), std::string("PF\n2 2\n-1\n"), text.substr(0, text.size() - 1),
                                 text + "x", std::string("skylit-xyz 1\n0 2\n"), std::string("skylit-xyz 1\n2 2 2\n"),
                                 std::string("skylit-xyz 1\n99999999 1\n"), not_finite}) {
    const std::string message = testing::input_error_of([&] { decode_xyz_file(bad, "shard.xyz"); });
    EXPECT_NE(message.find("shard.xyz"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace skylit
