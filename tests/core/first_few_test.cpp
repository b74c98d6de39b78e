// The list in a warning line that names what a model may have hundreds of.
#include <gtest/gtest.h>

#include "skylit/core/text_file.h"

namespace skylit {
namespace {

TEST(FirstFew, NamesTheFirstAndCountsTheRest) {
  EXPECT_EQ(first_few({}, 4), "");
  EXPECT_EQ(first_few({"'a'"}, 4), "'a'");
  EXPECT_EQ(first_few({"'a'", "'b'", "'c'", "'d'"}, 4), "'a', 'b', 'c', 'd'");
  EXPECT_EQ(first_few({"'a'", "'b'", "'c'", "'d'", "'e'", "'f'"}, 4), "'a', 'b', 'c', 'd' and 2 more");
}

}  // namespace
}  // namespace skylit
