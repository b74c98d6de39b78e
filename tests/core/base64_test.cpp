// base64_encode against the test vectors of RFC 4648, §10, and a byte of every value.
#include "skylit/core/base64.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace skylit {
namespace {

std::string encoded(const std::string& text) {
  return base64_encode(std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

TEST(Base64, Rfc4648TestVectors) {
  EXPECT_EQ(encoded(""), "");
  EXPECT_EQ(encoded("f"), "Zg==");
  EXPECT_EQ(encoded("fo"), "Zm8=");
  EXPECT_EQ(encoded("foo"), "Zm9v");
  EXPECT_EQ(encoded("foob"), "Zm9vYg==");
  EXPECT_EQ(encoded("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encoded("foobar"), "Zm9vYmFy");
}

TEST(Base64, HighBytesUseTheLastLettersOfTheAlphabet) {
  const std::vector<uint8_t> bytes{0xfb, 0xff, 0xbf};
  EXPECT_EQ(base64_encode(bytes), "+/+/");
}

}  // namespace
}  // namespace skylit
