// The pieces of --help and of the messages for mistakes: value lists whose
// name column fits their longest name, and "did you mean".
#include <gtest/gtest.h>

#include "tools/command_line.hpp"
#include "tools/nearest_word.hpp"

namespace umbra {
namespace {

TEST(HelpText, AValueListsNameColumnFitsItsLongestName) {
  const std::string rows = value_rows({{"auto", "the default"}, {"a-much-longer-name", "runs into nothing"}});
  const std::string indent(26, ' ');
  EXPECT_EQ(rows, indent + "auto                the default\n" + indent + "a-much-longer-name  runs into nothing\n");
  // A long help wraps in its own column.
  const std::string wrapped = value_rows({{"x", std::string(30, 'a') + " " + std::string(30, 'b')}});
  EXPECT_EQ(wrapped, indent + "x  " + std::string(30, 'a') + "\n" + std::string(29, ' ') + std::string(30, 'b') + "\n");
}

TEST(HelpText, TheNearestWordIsASlipOfTheFingersAway) {
  const std::vector<std::string> commands = {"render", "check", "view", "volume", "bench"};
  EXPECT_EQ(nearest_word("rendr", commands), "render");   // a letter left out
  EXPECT_EQ(nearest_word("chekc", commands), "check");    // two swapped
  EXPECT_EQ(nearest_word("veiw", commands), "view");
  EXPECT_EQ(nearest_word("volumes", commands), "volume");  // one added
  EXPECT_EQ(nearest_word("explode", commands), "");       // nothing near
  EXPECT_EQ(nearest_word("x", commands), "");
  EXPECT_EQ(did_you_mean("--antialais", {"--antialias", "--any-texture-path"}), " (did you mean --antialias?)");
  EXPECT_EQ(did_you_mean("--frobnicate", {"--antialias", "--size"}), "");
}

}  // namespace
}  // namespace umbra
