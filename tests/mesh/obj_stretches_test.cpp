// An OBJ file is read on every core in stretches of lines: however it is
// split, the soup (points, faces, their lines, materials, warnings) and the
// first error are those of one reading from start to end.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "mesh/input_error.hpp"
#include "mesh/io/mesh_readers.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

// Everything a reading gives, as text: a difference shows where it is.
std::string reading_of(const std::string& text, const std::string& path, size_t chunk_bytes) {
  std::ostringstream out;
  try {
    const PolygonSoup soup = read_obj(text, path, chunk_bytes);
    for (size_t i = 0; i < soup.points.size(); ++i)
      out << "v " << soup.points[i].x << " " << soup.points[i].y << " " << soup.points[i].z << " @" << soup.point_lines[i] << "\n";
    for (size_t f = 0; f < soup.polygon_count(); ++f) {
      out << "f";
      for (uint32_t c = 0; c < soup.corner_count(f); ++c) out << " " << soup.polygon(f)[c];
      out << " @" << soup.polygon_lines[f] << " material " << soup.polygon_material(f) << "\n";
    }
    for (const SoupMaterial& m : soup.materials) out << "material " << m.name << " " << m.diffuse.r << "\n";
    for (const ReadWarning& w : soup.warnings) out << "warning @" << w.line << ": " << w.message << "\n";
  } catch (const InputError& e) {
    out << "error " << e.what() << "\n";
  }
  return out.str();
}

// The reading in one stretch, then split every way that 1 to `text.size()`
// bytes a stretch gives.
void expect_every_split_reads_alike(const std::string& text, const std::string& path) {
  const std::string whole = reading_of(text, path, text.size() + 1);
  for (size_t chunk = 1; chunk <= text.size(); chunk += 1 + chunk / 8)
    ASSERT_EQ(reading_of(text, path, chunk), whole) << "in stretches of " << chunk << " bytes";
}

using ObjStretches = test::ScratchFolder;

// A strip of quads with every corner form, relative indices reaching back
// across many lines, CRLF and bare-CR line ends, blanks, comments and
// materials switched (one of them undefined) along the way.
std::string strip(int quads) {
  std::string obj = "# strip\r\nmtllib strip.mtl\n\n";
  for (int i = 0; i <= quads; ++i)
    obj += "v " + std::to_string(i) + " 0 0\n  v\t" + std::to_string(i) + " 1 0.5e0\r\nvn 0 0 1\nvt 0 0\r";
  for (int i = 0; i < quads; ++i) {
    if (i % 7 == 0) obj += std::string("usemtl ") + (i % 3 == 0 ? "red" : i % 3 == 1 ? "blue" : "plum") + "\n";
    const int a = 2 * i + 1;
    if (i % 2 == 0)
      obj += "f " + std::to_string(a) + " " + std::to_string(a + 2) + "/1 " + std::to_string(a + 3) + "//1 " +
             std::to_string(a + 1) + "/1/1\n";
    else  // counted back from the last point of the file so far
      obj += "f " + std::to_string(a - 2 * (quads + 1) - 1) + " " + std::to_string(a + 2 - 2 * (quads + 1) - 1) + " -" +
             std::to_string(2 * (quads + 1) - a - 2) + "\r\n";
  }
  return obj;
}

TEST_F(ObjStretches, EverySplitReadsAsTheWholeFile) {
  write("strip.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  const std::string text = strip(40);
  const std::string path = write("strip.obj", text);
  const std::string whole = reading_of(text, path, text.size() + 1);
  // What the whole reading says, checked by hand at a few places.
  EXPECT_NE(whole.find("v 0 1 0.5 @5\n"), std::string::npos) << whole;
  EXPECT_NE(whole.find("f 0 2 3 1 @"), std::string::npos);
  EXPECT_NE(whole.find(" material 0\n"), std::string::npos);
  EXPECT_NE(whole.find(" material 1\n"), std::string::npos);
  EXPECT_NE(whole.find(" material -1\n"), std::string::npos);  // after "usemtl plum"
  EXPECT_NE(whole.find("warning @"), std::string::npos);
  EXPECT_EQ(whole.find("error"), std::string::npos) << whole;
  expect_every_split_reads_alike(text, path);
}

TEST_F(ObjStretches, TheFirstErrorIsNamedWhicheverStretchFindsOneFirst) {
  std::string text = strip(30);
  // A relative index that reaches before the first point, then a coordinate
  // that is not a number: the first is the error, in every split.
  text += "f 1 2 -200\nv 0 nan 0\n";
  const std::string path = write("strip.obj", text);
  write("strip.mtl", "newmtl red\nKd 1 0 0\n");
  const std::string whole = reading_of(text, path, text.size() + 1);
  EXPECT_NE(whole.find("relative vertex index -200 points before the first vertex (only 62 defined so far)"), std::string::npos)
      << whole;
  expect_every_split_reads_alike(text, path);
  // A material library's unreadable statement is only a warning: the first
  // error is still the file's own, in every split.
  write("strip.mtl", "newmtl red\nKd 1 x 0\n");
  const std::string library_broken = reading_of(text, path, text.size() + 1);
  EXPECT_NE(library_broken.find("relative vertex index -200 points before the first vertex"), std::string::npos) << library_broken;
  EXPECT_EQ(library_broken.find("strip.mtl:2:6"), std::string::npos) << library_broken;
  expect_every_split_reads_alike(text, path);
}

TEST(ObjStretchesOfRealFiles, ExportersFilesReadAlikeHoweverSplit) {
  const std::filesystem::path models = "/usr/share/assimp/models/OBJ";
  if (!std::filesystem::exists(models)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(models)) {
    if (entry.path().extension() != ".obj") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string whole = reading_of(text, entry.path().string(), text.size() + 1);
    for (const size_t chunk : {size_t(1), size_t(100), size_t(4096), text.size() / 3 + 1})
      EXPECT_EQ(reading_of(text, entry.path().string(), chunk), whole) << entry.path() << " in stretches of " << chunk << " bytes";
    ++files;
  }
  EXPECT_GE(files, 20);
}

}  // namespace
}  // namespace umbra
