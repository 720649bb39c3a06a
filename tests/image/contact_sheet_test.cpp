// A contact sheet's labels: any bytes a file name holds are drawn safely
// (the font has printable ASCII only), and labels too long for their tile
// keep what tells the files apart.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/contact_sheet.hpp"
#include "image/text_drawing.hpp"

namespace umbra {
namespace {

// The label band under the first tile of a one-picture sheet.
std::vector<uint8_t> label_of(const std::string& label, int columns = 1, const std::vector<std::string>& others = {}) {
  std::vector<SheetPicture> pictures{{label, Image(120, 40, 3, 200), ""}};
  for (const std::string& o : others) pictures.push_back({o, Image(120, 40, 3, 200), ""});
  const Image sheet = contact_sheet(pictures, 120, columns);
  std::vector<uint8_t> band;
  for (int y = 6 + 40; y < 6 + 40 + 24; ++y)
    for (int x = 6; x < 6 + 120; ++x) band.push_back(sheet.at(x, y, 0));
  return band;
}

// DEL and bytes past 0x7f once indexed outside stb_easy_font's tables
// (AddressSanitizer's global-buffer-overflow); each character is now a '?'.
TEST(ContactSheet, BytesOutsidePrintableAsciiAreDrawnAsQuestionMarks) {
  EXPECT_EQ(label_of("a\x7f" "b.off"), label_of("a?b.off"));
  EXPECT_EQ(label_of("\xc3\xa9 \xc3\xbc.off"), label_of("? ?.off"));  // "é ü.off": one '?' a character
  EXPECT_EQ(label_of("tab\there"), label_of("tab?here"));
  EXPECT_NE(label_of("a?b.off"), label_of("a_b.off"));  // the band shows the label at all
}

// Four files whose long names differ only in their folders: each label
// keeps the part that differs, not the file name they share.
TEST(ContactSheet, LongLabelsKeepWhatTellsThemApart) {
  const std::vector<std::string> names = {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                                          "BoxTextured-glTF-Embedded/BoxTextured.gltf",
                                          "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf"};
  std::vector<std::vector<uint8_t>> bands;
  for (size_t k = 0; k < names.size(); ++k) {
    std::vector<std::string> others;
    for (size_t j = 0; j < names.size(); ++j)
      if (j != k) others.push_back(names[j]);
    bands.push_back(label_of(names[k], 4, others));
  }
  for (size_t a = 0; a < bands.size(); ++a)
    for (size_t b = a + 1; b < bands.size(); ++b) EXPECT_NE(bands[a], bands[b]) << names[a] << " and " << names[b];
}

// Sixteen files whose long paths differ only at the end of their stems (a
// test suite's numbered files): each label is the longest end of its stem
// that fits, "...e_07", not the front and the shared extension, which once
// made thirty tiles read alike ("glTF2....gltf").
TEST(ContactSheet, NumberedFilesShowTheEndOfTheirStem) {
  std::vector<std::string> names;
  for (int k = 0; k < 16; ++k)
    names.push_back("glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_" + std::string(k < 10 ? "0" : "") +
                    std::to_string(k) + ".gltf");
  for (const int k : {0, 7, 15}) {
    std::vector<std::string> others;
    for (const std::string& n : names)
      if (n != names[size_t(k)]) others.push_back(n);
    const std::string stem = names[size_t(k)].substr(names[size_t(k)].rfind('/') + 1, std::string("Mesh_PrimitiveMode_00").size());
    std::string expected;
    for (size_t keep = 1; keep <= stem.size() && text_width("..." + stem.substr(stem.size() - keep)) <= 120; ++keep)
      expected = "..." + stem.substr(stem.size() - keep);
    ASSERT_GT(expected.size(), 5u);
    EXPECT_EQ(label_of(names[size_t(k)], 4, others), label_of(expected)) << names[size_t(k)] << " should read " << expected;
  }
}

}  // namespace
}  // namespace umbra
