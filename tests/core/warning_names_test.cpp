// How warning lines name what a user's files give: a list of what a model may have
// hundreds of, and one name, whole, however long or foreign.
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

// Two texture paths that share their first 20 bytes read the same when cut there (an
// outside trial's "textures/facade/bric..." twice): shown whole up to 120 bytes; UTF-8
// kept, cut only between characters; control characters as '?'.
TEST(QuoteName, ShowsLongNamesWholeAndCutsOnlyBetweenCharacters) {
  EXPECT_EQ(quote_name("textures/facade/brick_red_01.png"), "'textures/facade/brick_red_01.png'");
  EXPECT_NE(quote_name("textures/facade/brick_red_01.png"), quote_name("textures/facade/brick_red_02.png"));
  const std::string facade = std::string("Fa") + "\xC3\xA7" + "ade";  // "Façade" in UTF-8
  EXPECT_EQ(quote_name(facade), "'" + facade + "'");
  EXPECT_EQ(quote_name("a\nb\x7F"), "'a?b?'");
  const std::string long_name = std::string(119, 'x') + "\xC3\xA7" + "tail";  // ç across the 120th byte
  EXPECT_EQ(quote_name(long_name), "'" + std::string(119, 'x') + "...'");
  EXPECT_EQ(quote_name(std::string(120, 'y')), "'" + std::string(120, 'y') + "'");
}

}  // namespace
}  // namespace skylit
