// Files in the formats umbra reads through libraries, as the commands meet
// them: Assimp's told by name in a folder unless plainly something else,
// named by their importer in the check, and refused saying which importer
// could not read them; CAD exchange files through Open CASCADE, told by
// their content, whose solids check closed.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <fstream>
#include <iterator>

#include "mesh/io/mesh_file.hpp"
#include "mesh/io/mesh_format.hpp"
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

// A coordinate that is not a number is the file's defect, named as umbra's
// own readers name it, whether the file holds it or its frames' transforms
// overflow to it; and no picture is written.
TEST_F(AssimpFiles, ACoordinateThatIsNoNumberIsNamed) {
  const std::string frame = "  FrameTransformMatrix { 1.0e30, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;; }\n";
  const std::string mesh = "  Mesh { 3; 0.0; 0.0; 0.0;, X; 0.0; 0.0;, 0.0; 1.0; 0.0;; 1; 3; 0, 1, 2;; }\n";
  const auto with_x = [&](const std::string& x) { return std::string(mesh).replace(mesh.find('X'), 1, x); };
  const std::string held = write("held.x", "xof 0303txt 0032\nFrame Root {\n" + with_x("nan") + "}\n");
  const std::string placed = write("placed.x", "xof 0303txt 0032\nFrame Root {\n" + frame + "Frame Child {\n" + frame + with_x("1.0") + "}\n}\n");
  CommandResult r = run("check " + held);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, held + ": mesh 0 vertex 1 has a coordinate that is not a finite number\n");
  r = run("render " + placed + " --size 32x32 -o " + path("placed.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, placed + ": mesh 0 vertex 0 has a coordinate that is not a finite number once placed by its node's transform\n");
  EXPECT_FALSE(fs::exists(path("placed.png")));
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

// A STEP file's colours (its styles, read through XCAF) are its faces'
// materials: tests/data/coloured-boxes.step, written by Open CASCADE 7.6's
// STEPCAFControl_Writer, has a box coloured red as a part, and a box of
// which only the top face is coloured, blue.
TEST_F(CadFiles, AStepFilesColoursAreItsFacesMaterials) {
  const PolygonSoup soup = read_polygon_soup(std::string(UMBRA_SOURCE_DIR) + "/tests/data/coloured-boxes.step");
  ASSERT_EQ(soup.materials.size(), 2u);
  ASSERT_EQ(soup.polygon_materials.size(), soup.polygon_count());
  std::map<std::string, size_t> faces_of;
  for (size_t f = 0; f < soup.polygon_count(); ++f) {
    const int m = soup.polygon_material(f);
    ++faces_of[m < 0 ? "none" : soup.materials[size_t(m)].name];
    if (m >= 0) {
      EXPECT_EQ(soup.materials[size_t(m)].diffuse, soup.materials[size_t(m)].name == "#ff0000" ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1));
    }
  }
  EXPECT_EQ(faces_of, (std::map<std::string, size_t>{{"#ff0000", 12}, {"#0000ff", 2}, {"none", 10}}));
}

// A SystemTap script, which is named .stp too, is no STEP file: it has not
// STEP's header, and is passed over as no mesh (not failed as a STEP file
// that Open CASCADE could not read).
TEST_F(CadFiles, AnStpFileWithoutStepsHeaderIsNoMesh) {
  const std::string probe = path("probe.stp");
  std::ofstream(probe) << "global count\nprobe syscall.open { count++ }\n";
  const CommandResult r = run("check " + probe);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, probe + ": not a mesh file (" + mesh_format_names() + "): text starting with \"global\"\n");
}

// --cad-deflection and --cad-angle cut the screw's surfaces coarser or
// finer (918 triangles by default), and it checks closed at each; a value
// out of range is refused naming its range.
TEST_F(CadFiles, TheTessellationIsTheUsersToChoose) {
  const std::string screw = "/usr/share/opencascade/data/step/screw.step";
  if (!fs::exists(screw)) GTEST_SKIP() << "needs Debian's occt-misc (build.sh installs it)";
  const auto triangles = [&](const std::string& options) {
    const CommandResult r = run("check " + screw + " --brief " + options);
    EXPECT_EQ(r.status, 0) << options << ": " << r.out << r.err;
    const size_t end = r.out.find(" triangles, 1 component: closed 2-manifold");
    EXPECT_NE(end, std::string::npos) << r.out;
    return std::stoul(r.out.substr(r.out.rfind(' ', end - 1) + 1));
  };
  const size_t coarse = triangles("--cad-deflection 0.01"), usual = triangles(""), smoother = triangles("--cad-angle 10");
  EXPECT_EQ(usual, 918u);
  EXPECT_LT(coarse, usual);
  EXPECT_GT(smoother, usual);
  CommandResult r = run("render " + screw + " --cad-angle 0.5 -o " + path("screw.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --cad-angle expects degrees from 1 to 90, got \"0.5\"\n(see umbra render --help)\n");
  r = run("check " + screw + " --cad-deflection 0");
  EXPECT_EQ(r.err, "umbra check: --cad-deflection expects a fraction of the model's size from 1e-06 to 0.1, got \"0\"\n(see umbra check --help)\n");
  EXPECT_EQ(run("render " + screw + " --size 64x48 --cad-deflection 0.01 -o " + path("screw.png")).status, 0);
  EXPECT_TRUE(fs::exists(path("screw.png")));
}

// A BREP cut short is refused saying so, and Open CASCADE prints nothing
// (it found "no shape", printing "Not a TShape table"; another broken BREP
// kept its reader looking for a number past the end without end:
// fuzz/regressions/library/).
TEST_F(CadFiles, ABrepCutShortIsRefused) {
  const std::string brep = "/usr/share/opencascade/data/occ/MODERN_Table_1.brep";
  if (!fs::exists(brep)) GTEST_SKIP() << "needs Debian's occt-misc (build.sh installs it)";
  std::ifstream in(brep, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string cut = path("cut.brep");
  std::ofstream(cut, std::ios::binary) << text.substr(0, text.size() / 2);
  const CommandResult r = run("check " + cut);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, cut + ": Open CASCADE's BREP reader cannot read it: it ends before its shapes do, or holds text where a number belongs\n");
}

}  // namespace
}  // namespace umbra
