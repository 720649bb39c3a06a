// Files in the formats umbra reads through libraries, as the commands meet
// them: Assimp's told by name in a folder unless plainly something else,
// named by their importer in the check, and refused saying which importer
// could not read them; CAD exchange files through Open CASCADE, told by
// their content, whose solids check closed.

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

using test::CommandResult;
namespace fs = std::filesystem;

const std::string kModels = "/usr/share/assimp/models/";

class AssimpFiles : public test::CommandTest {
 protected:
  void SetUp() override {
    test::CommandTest::SetUp();
    if (!fs::exists(kModels + "3DS/fels.3ds")) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  }
  std::string write(const std::string& name, const std::string& text) const {
    fs::create_directories(fs::path(path(name)).parent_path());
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
};

// A folder of a 3DS rock, a JPEG named .3ds and Collada that is no
// Collada: the rock drawn, the JPEG passed over saying what it is, the
// broken file failed naming the importer that could not read it.
TEST_F(AssimpFiles, AFoldersFilesAreToldByNameAndEachHasItsRecord) {
  fs::create_directories(path("in"));
  fs::copy_file(kModels + "3DS/fels.3ds", path("in/fels.3ds"));
  write("in/photo.3ds", std::string("\xff\xd8\xff\xe0\0\x10JFIF", 10));
  write("in/broken.dae", "<?xml version=\"1.0\"?>\n<COLLADA><library_geometries>\n");
  const CommandResult r = run("render " + path("in") + " --size 48x48 --json -o " + path("out"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("{\"path\":\"" + path("in/fels.3ds") + "\",\"picture\":\"" + path("out/fels.3ds.png") + "\",\"status\":\"drawn\""),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("{\"path\":\"" + path("in/photo.3ds") + "\",\"picture\":null,\"status\":\"passed over\",\"kind\":\"unsupported-format\""),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find("umbra render: passed over " + path("in/photo.3ds") + ": a JPEG image, not a mesh\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(path("in/broken.dae") + ": Assimp's Collada Importer cannot read it: "), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(path("out/fels.3ds.png")));
}

// The check names the importer, and reads what it gives: Collada's duck is
// one closed surface.
TEST_F(AssimpFiles, TheCheckNamesTheImporter) {
  const CommandResult r = run("check " + kModels + "Collada/duck.dae");
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')),
            kModels + "Collada/duck.dae: read through Assimp's Collada Importer, 8500 vertices, 2144 faces (4212 triangles)");
  EXPECT_NE(r.out.find("components         1 (1 closed)"), std::string::npos) << r.out;
}

class FormatsCommand : public test::CommandTest {};

// umbra formats prints the formats' table, and docs/check.md shows exactly that.
TEST_F(FormatsCommand, TheDocsShowWhatItPrints) {
  const CommandResult r = run("formats");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')), "format            extensions                    told by  read by");
  EXPECT_NE(r.out.find("\nSTEP              .step .stp                    content  Open CASCADE\n"), std::string::npos) << r.out;
  const std::string docs = read(std::string(UMBRA_SOURCE_DIR) + "/docs/check.md");
  EXPECT_NE(docs.find("```\n" + r.out + "```\n"), std::string::npos) << "docs/check.md's copy of umbra formats differs from:\n" << r.out;
  for (const std::string line : {"umbra formats", "umbra formats --help"}) EXPECT_EQ(run(line.substr(6)).status, 0) << line;
}

class CadFiles : public test::CommandTest {};

// A STEP solid checks closed, so the check exits 0, under any name (told
// by its content); IGES's faces, which its file does not join into shells,
// check open; an IFC file, written as STEP is, stays Assimp's.
TEST_F(CadFiles, AStepSolidChecksClosedUnderAnyName) {
  const std::string data = "/usr/share/opencascade/data/";
  if (!fs::exists(data + "step/screw.step")) GTEST_SKIP() << "needs Debian's occt-misc (build.sh installs it)";
  fs::copy_file(data + "step/screw.step", path("screw.txt"));
  for (const std::string& file : {data + "step/screw.step", path("screw.txt")}) {
    const CommandResult r = run("check " + file);
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_EQ(r.out.substr(0, r.out.find('\n')), file + ": STEP, tessellated by Open CASCADE, 638 vertices, 918 faces (918 triangles)");
    EXPECT_NE(r.out.find("components         1 (1 closed)"), std::string::npos) << r.out;
  }
  const CommandResult iges = run("check " + data + "iges/bearing.iges");
  EXPECT_EQ(iges.out.substr(0, iges.out.find(',')), data + "iges/bearing.iges: IGES");
  EXPECT_NE(iges.out.find("(0 closed)"), std::string::npos) << iges.out;
  const std::string ifc = kModels + "IFC/AC14-FZK-Haus.ifc";
  if (fs::exists(ifc)) {
    const CommandResult r = run("check " + ifc);
    EXPECT_EQ(r.out.substr(0, r.out.find(',')), ifc + ": read through Assimp's Industry Foundation Classes (IFC) Importer");
  }
}

}  // namespace
}  // namespace umbra
