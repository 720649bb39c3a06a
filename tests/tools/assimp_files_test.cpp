// Files in the formats umbra reads through Assimp, as the commands meet
// them: told by name in a folder unless plainly something else, named by
// their importer in the check, and refused saying which importer could not
// read them.

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

}  // namespace
}  // namespace umbra
