// The pieces of --help and of the messages for mistakes: value lists whose
// name column fits their longest name, and "did you mean".
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/io/mesh_format.hpp"
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

// An option's help, its range and its default come from its one definition:
// --help's column, the Markdown table of docs/options.md, and the message for
// a value out of range all say the same numbers.
TEST(HelpText, AnOptionsHelpAndRangeComeFromItsDefinition) {
  int samples = 2;
  bool quick = false;
  constexpr ValueRange kSamples{1, 4};
  CommandOptions options;
  options.value("--samples", ranged({"N", "samples per pixel, {range} (default {default})"}, kSamples, samples),
                [&](const std::string& o, const std::string& t) { samples = parse_int_in(o, t, kSamples); });
  options.paragraph("How fast:");
  options.flag("--quick", quick, "one | two");
  options.help_option();
  EXPECT_EQ(options.help_text(), "  --samples N           samples per pixel, 1 to 4 (default 2)\n"
                                 "\n"
                                 "  How fast:\n"
                                 "  --quick               one | two\n"
                                 "  -h, --help            show this help\n");
  EXPECT_EQ(options.markdown(), "| option | what it does |\n|---|---|\n| `--samples N` | samples per pixel, 1 to 4 (default 2) |\n\n"
                                "How fast:\n\n"
                                "| option | what it does |\n|---|---|\n| `--quick` | one \\| two |\n| `-h, --help` | show this help |\n");
  try {
    options.parse({"--samples", "5"});
    ADD_FAILURE() << "5 is out of range";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "--samples expects a whole number from 1 to 4, got \"5\"");
  }
  try {
    options.parse({"--quick", "-h"});
    ADD_FAILURE() << "-h asks for help";
  } catch (const HelpRequest& help) {
    EXPECT_EQ(help.options, options.help_text());
  }
  options.parse({"--samples=3"});
  EXPECT_EQ(samples, 3);
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

// The lists of formats a reader meets in docs/check.md are the table's
// (mesh_format.hpp), checked here where they are written out: a format
// added to the table fails this test until check.md names it too. (The
// methods' lists are all written from their table: --help, docs/options.md.)
std::string doc(const std::string& name) {
  std::ifstream in(std::string(UMBRA_SOURCE_DIR) + "/" + name);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_FALSE(text.str().empty()) << name;
  return text.str();
}

// Where the docs say which formats umbra reads itself (the rows the mesh
// fuzzer covers: its own readers, tinygltf's and lib3mf's), they name those
// rows, in the table's order.
TEST(DocLists, TheFormatsUmbraReadsItselfAreTheTables) {
  std::vector<std::string> own;
  for (const MeshFormat& f : mesh_formats())
    if (f.fuzzed) own.emplace_back(f.name);
  const auto names = [](std::string list) {
    list = std::regex_replace(list, std::regex(" 2\\.0|\\n"), " ");
    std::vector<std::string> found;
    std::smatch word;
    for (std::string rest = list; std::regex_search(rest, word, std::regex("[A-Za-z0-9]+")); rest = word.suffix().str())
      if (word.str() != "and" && word.str() != "or") found.push_back(word.str());
    return found;
  };
  std::smatch match;
  const std::string check = doc("docs/check.md");
  ASSERT_TRUE(std::regex_search(check, match, std::regex("Reads each mesh \\(([A-Za-z0-9., \\n]*);")));
  EXPECT_EQ(names(match[1]), own);
  ASSERT_TRUE(std::regex_search(check, match, std::regex("umbra reads ([A-Za-z0-9., \\n]*?) itself")));
  EXPECT_EQ(names(match[1]), own);
}

// rendering.md's colour names are parse_color's table, in its order.
TEST(DocLists, RenderingMdNamesTheColoursTheOptionsTake) {
  std::smatch match;
  const std::string rendering = doc("docs/rendering.md");
  ASSERT_TRUE(std::regex_search(rendering, match, std::regex("one of the names ([a-z, \\n]+?) \\(CSS")));
  std::vector<std::string> names;
  std::istringstream words(std::regex_replace(match[1].str(), std::regex("[,\\n]"), " "));
  for (std::string word; words >> word;)
    if (word != "and") names.push_back(word);
  EXPECT_EQ(names, color_names());
}

// The message check.md shows for a file of no mesh format names the
// formats as the program does (mesh_format_names()).
TEST(DocLists, CheckMdNamesTheFormatsAsTheMessageDoes) {
  const std::string check = doc("docs/check.md");
  EXPECT_NE(check.find("README.obj: not a mesh file (" + mesh_format_names() + "): text starting with"), std::string::npos)
      << mesh_format_names();
}

}  // namespace
}  // namespace umbra
