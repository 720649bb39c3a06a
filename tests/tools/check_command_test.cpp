// `umbra check` as a user meets it: reports in order, exit codes, JSON lines,
// repair that never touches its input.
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include <sstream>

#include "image/image.hpp"
#include "mesh/io/mesh_format.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

using test::CommandResult;
namespace fs = std::filesystem;

using test::obj_text;

class CheckCommand : public test::CommandTest {};

TEST_F(CheckCommand, ClosedMeshExitsZeroWithItsVerdict) {
  const CommandResult r = run("check " + write("tet.obj", obj_text(test::tetrahedron())));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(path("tet.obj") + ": OBJ, 4 vertices, 4 faces (4 triangles)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  verdict            closed 2-manifold: casts its shadow from silhouette edges\n"), std::string::npos);
  EXPECT_EQ(r.err, "");
}

TEST_F(CheckCommand, SeveralMeshesAreReportedInTheOrderGiven) {
  const std::string open = write("open.obj", obj_text(test::without_faces(test::unit_cube(), {4, 5})));
  const std::string closed = write("closed.obj", obj_text(test::unit_cube()));
  const CommandResult r = run("check " + open + " " + closed + " " + open);
  EXPECT_EQ(r.status, 1);
  const size_t first = r.out.find(open + ": OBJ");
  const size_t second = r.out.find(closed + ": OBJ");
  const size_t third = r.out.find(open + ": OBJ", first + 1);
  EXPECT_LT(first, second);
  EXPECT_LT(second, third);
  EXPECT_NE(third, std::string::npos);
  EXPECT_NE(r.out.find("not a closed 2-manifold (4 border edges in 1 hole): shadow from an edge-multiplicity volume (exact for any triangles)"),
            std::string::npos);
}

TEST_F(CheckCommand, UnreadableMeshExitsTwoWithItsLocatedError) {
  const std::string bad = write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  const std::string good = write("good.obj", obj_text(test::tetrahedron()));
  const CommandResult r = run("check " + good + " " + bad);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.substr(0, r.err.find("umbra check: ")),
            bad + ":4: face 0 refers to vertex 3 (counting from 0), but the file has 3 vertices\n");
  EXPECT_NE(r.out.find(good + ": OBJ"), std::string::npos);
}

// --brief: one line per mesh, its path first, so that grep keeps which
// file each verdict is about; an unreadable mesh has its line too.
// --solid gates the exit status on a printer's solid: an inward tetrahedron
// is a closed 2-manifold (exit 0) but no solid (exit 1, and the report says
// why); the JSON carries the corpus flags.
TEST_F(CheckCommand, SolidGatesTheExitStatusOnAPrintersSolid) {
  const std::string inward = write("inward.obj", obj_text(test::all_reversed(test::tetrahedron())));
  EXPECT_EQ(run("check " + inward).status, 0);
  const CommandResult r = run("check --solid " + inward);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("\n  solid              no: inside out (1 closed component faces inward)\n"), std::string::npos) << r.out;
  const std::string clean = write("clean.obj", obj_text(test::tetrahedron()));
  EXPECT_EQ(run("check --solid " + clean).status, 0);
  const CommandResult json = run("check --json " + inward);
  for (const char* flag : {"\"closed\":true", "\"edge_manifold\":true", "\"vertex_manifold\":true", "\"oriented\":true",
                           "\"self_intersecting\":false", "\"solid\":false", "\"solid_problems\":[\"inside out (1 closed component faces inward)\"]"})
    EXPECT_NE(json.out.find(flag), std::string::npos) << flag << "\n" << json.out;
}

TEST_F(CheckCommand, BriefIsOneLinePerMeshWithItsPathAndVerdict) {
  const std::string meshes = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/";
  const std::string missing = path("missing.obj");
  const CommandResult r = run("check --brief " + meshes + "open_box.obj " + meshes + "pair.off " + missing);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, meshes + "open_box.obj: OBJ, 10 triangles, 1 component: not a closed 2-manifold (4 border edges in 1 hole): "
                            "shadow from an edge-multiplicity volume (exact for any triangles)\n" +
                   meshes + "pair.off: OFF, 16 triangles, 2 components: closed 2-manifold: casts its shadow from silhouette edges\n" +
                   missing + ": cannot open: No such file or directory\n");
  EXPECT_NE(r.err.find(" s: 1 closed 2-manifold, 1 not, 1 unreadable\n"), std::string::npos) << r.err;  // only the summary on stderr
  EXPECT_EQ(r.err.rfind("umbra check: 3 meshes in ", 0), 0u) << r.err;
  const CommandResult both = run("check --brief --json " + meshes + "pair.off");
  EXPECT_EQ(both.status, 2);
  EXPECT_EQ(both.err, "umbra check: --json and --brief are two forms of the same report: give one\n(see umbra check --help)\n");
}

// A file with points and no faces is no mesh to shadow: its verdict says so,
// not which shadow volume it would get.
TEST_F(CheckCommand, AFileWithNoFacesHasNothingToShadow) {
  const std::string points = write("points.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                                 "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
  const CommandResult r = run("check --brief " + points);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, points + ": PLY (ascii), 0 triangles, 0 components: no faces: nothing to check, and nothing to cast a shadow\n");
}

TEST_F(CheckCommand, JsonIsOneValidObjectPerMeshPerLine) {
  const std::string bad = write("bad \"name\".off", "OFF\n1 0 0\n");
  const std::string good = write("good.obj", obj_text(test::unit_cube()));
  const std::string flipped = write("flipped.obj", obj_text(test::reversed(test::unit_cube(), {7})));
  const CommandResult r = run("check --json " + good + " '" + bad + "' " + flipped);
  EXPECT_EQ(r.status, 2);
  // Python's json module is the judge of validity; it prints the fields we ask for.
  std::ofstream(path("out.json")) << r.out;
  const std::string script =
      "import json,sys\n"
      "for line in open(sys.argv[1]):\n"
      "  o = json.loads(line)\n"
      "  print(o['path'].split('/')[-1], o.get('closed_manifold'), o.get('faces_to_flip'), o.get('shadow_method'),"
      " 'error' in o, o.get('examples', {}).get('faces_to_flip'))\n";
  std::ofstream(path("read.py")) << script;
  const int status = std::system(("python3 " + path("read.py") + " " + path("out.json") + " >" + path("fields.txt")).c_str());
  ASSERT_EQ(status, 0) << r.out;
  EXPECT_EQ(read(path("fields.txt")),
            "good.obj True 0 silhouette False []\n"
            "bad \"name\".off None None None True None\n"
            // Face 7, quad 3's second triangle: (0, 1, 0), (1, 1, 1), (1, 1, 0), its mean where it is.
            "flipped.obj False 1 silhouette False [{'face': 7, 'line': 16, 'at': [0.6666666666666666, 1.0, 0.3333333333333333]}]\n");
}

TEST_F(CheckCommand, JsonHasALineForEveryMeshEvenWhenItsCheckRunsOutOfMemory) {
  // A strip of 400,000 triangles as binary STL (20 MB), checked with the
  // address space capped at 140 MB, which starting takes under 100 MB of:
  // the check of the strip fails for want of memory; its line says so.
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves far more address space than the cap";
#endif
  std::string stl(80, ' ');
  const uint32_t count = 400000;
  stl.append(reinterpret_cast<const char*>(&count), 4);
  for (uint32_t i = 0; i < count; ++i) {
    const float record[12] = {0, 0, 1, float(i), 0, 0, float(i) + 1, 0, 0, float(i), 1, 0};
    stl.append(reinterpret_cast<const char*>(record), sizeof record);
    stl.append(2, '\0');
  }
  const std::string strip = write("strip.stl", stl);
  const std::string good = write("good.obj", obj_text(test::unit_cube()));
  const CommandResult r = run("check --json --jobs 1 " + good + " " + strip, "ulimit -v 140000; ");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.substr(0, r.err.find("umbra check: ")), strip + ": not enough memory to check this mesh\n");
  const size_t second = r.out.find('\n') + 1;
  ASSERT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2) << r.out;
  EXPECT_EQ(r.out.substr(second), "{\"path\":\"" + strip + "\",\"error\":\"" + strip + ": not enough memory to check this mesh\"}\n");
}

TEST_F(CheckCommand, JsonIsValidUtf8EvenForFileNamesThatAreNot) {
  // Latin-1 "café.obj" and "broken-é.off": the é is the single byte 0xE9.
  const std::string good = write("caf\xe9.obj", obj_text(test::tetrahedron()));
  const std::string bad = write("broken-\xe9.off", "OFF\n1 0 0\n");
  const CommandResult r = run("check --json '" + good + "' '" + bad + "'");
  EXPECT_EQ(r.status, 2);
  std::ofstream(path("out.json")) << r.out;
  // Python decodes strictly as UTF-8, then parses strictly as JSON.
  std::ofstream(path("strict.py")) << "import json,sys\n"
                                      "text = open(sys.argv[1], 'rb').read().decode('utf-8', errors='strict')\n"
                                      "for line in text.splitlines():\n"
                                      "  o = json.loads(line)\n"
                                      "  print(o['path'].split('/')[-1].encode('unicode_escape').decode(), 'error' in o)\n";
  ASSERT_EQ(std::system(("python3 " + path("strict.py") + " " + path("out.json") + " >" + path("names.txt")).c_str()), 0) << r.out;
  EXPECT_EQ(read(path("names.txt")), "caf\\ufffd.obj False\nbroken-\\ufffd.off True\n");
}

TEST_F(CheckCommand, RepairFixesOrientationAndDuplicatesAndLeavesTheInputAlone) {
  PolygonSoup soup = test::reversed(test::unit_cube(), {3, 8});
  soup.corners.insert(soup.corners.end(), {0, 2, 3});  // a duplicate of face 0
  soup.end_polygon(0);
  const std::string input = write("in.obj", obj_text(soup));
  const std::string before = read(input);
  const CommandResult r = run("check " + input + " --repair " + path("out.off"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  removed 1 duplicate face\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  flipped 2 faces to orient them consistently\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(path("out.off") + ": OFF, 8 vertices, 12 faces"), std::string::npos);
  EXPECT_NE(r.out.find("verdict            closed 2-manifold"), std::string::npos);
  EXPECT_EQ(read(input), before);
  EXPECT_EQ(run("check " + path("out.off")).status, 0);
}

TEST_F(CheckCommand, RepairTurnsAnInwardMeshOutward) {
  const std::string input = write("in.obj", obj_text(test::all_reversed(test::tetrahedron())));
  const CommandResult r = run("check " + input + " --repair " + path("out.stl"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("  turned 1 closed component outward\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("component 0        4 faces, closed, chi 2, genus 0, outward, encloses 0.166667; silhouette volume\n"),
            std::string::npos)
      << r.out;
}

TEST_F(CheckCommand, RepairKeepsAHollowSolidsCavityFacingTheCavity) {
  const std::string input = write("hollow.obj", obj_text(test::hollow_cube()));
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  nothing to change\n"), std::string::npos) << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.obj")), glm::dvec3(1.5)), 26.0, 1e-9);
}

TEST_F(CheckCommand, RepairKeepsASmallBoxFarFromTheOriginOutward) {
  // A box of 1.5 x 0.5 x 1 with its corner at (9e8, 1.1e9, 7e8): summed about
  // the origin, its volume's terms (about 1e27 each) cancel to noise.
  PolygonSoup box = test::box_quads({9e8, 1.1e9, 7e8}, {9e8 + 1.5, 1.1e9 + 0.5, 7e8 + 1.0});
  const std::string input = write("far.obj", obj_text(box));
  ASSERT_NE(run("check " + input).out.find("genus 0, outward, encloses 0.75; silhouette volume\n"), std::string::npos);
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("closed, chi 2, genus 0, outward, encloses 0.75; silhouette volume\n"), std::string::npos) << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.obj")), {9e8, 1.1e9, 7e8}), 0.75, 1e-9);
}

// An L-shaped prism (3) and a box (0.36) poking half out of it (0.18 inside):
// the repair makes them the one solid that bounds their union, 3.18.
TEST_F(CheckCommand, RepairMergesShellsThatCrossIntoTheirUnion) {
  const std::string input = write("in.obj", obj_text(test::box_through_l_prism()));
  ASSERT_NE(run("check " + input).out.find("2 closed components cross faces: which way they face is undecided"), std::string::npos);
  const CommandResult r = run("check " + input + " --repair " + path("out.obj") + " --solid");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  removed the 11 pairs of triangles that cross: the parts that overlapped are one surface, bounding their union "
                       "(46 triangles now)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("component 0        46 faces, closed, chi 2, genus 0, outward, encloses 3.18; silhouette volume\n"), std::string::npos)
      << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.obj")), glm::dvec3(1.0)), 3.18, 1e-12);
}

// An open box of quads at coordinates the arithmetic cannot square or cube
// (1e77: a flat-part test overflowed and the hole was left; 1e200: a NaN
// volume, the box called inward and "turned outward"; 1e-200: a volume of
// 0, called inward): repaired at a power of two's scale, which is exact, to
// the closed outward box, every corner where the file has it.
TEST_F(CheckCommand, RepairHoldsCoordinatesPastWhatTheirCubesHold) {
  for (const char* scale : {"1e77", "1e200", "1e-200"}) {
    SCOPED_TRACE(scale);
    std::string obj;
    for (const char* corner : {"0 0 0", "1 0 0", "1 1 0", "0 1 0", "0 0 1", "1 0 1", "1 1 1", "0 1 1"}) {
      std::istringstream in(corner);
      obj += "v";
      for (int k = 0; k < 3; ++k) {
        int unit = 0;
        in >> unit;
        obj += unit ? std::string(" ") + scale : std::string(" 0");
      }
      obj += "\n";
    }
    obj += "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n";  // the side 4 1 5 8 missing
    const std::string input = write("box.obj", obj);
    const CommandResult r = run("check " + input + " --repair " + path("fixed.obj"));
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("  filled 1 hole with 2 triangles"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("turned"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("12 faces, closed, chi 2, genus 0, outward, encloses "), std::string::npos) << r.out;
    const PolygonSoup out = read_polygon_soup(path("fixed.obj"));
    std::set<std::tuple<double, double, double>> corners;
    for (const glm::dvec3& p : out.points) corners.insert({p.x, p.y, p.z});
    const double s = std::stod(scale);
    EXPECT_EQ(corners.size(), 8u);
    EXPECT_TRUE(corners.count({s, s, s}) && corners.count({0, s, 0})) << "the corners moved";
  }
}

// A folder repaired into a folder, its layout kept as a folder render keeps
// it: each mesh in its own format, one the repair cannot write (glTF) as
// OBJ beside its name; the output must be a folder.
TEST_F(CheckCommand, AFolderIsRepairedIntoAFolderOfTheSameLayout) {
  fs::create_directories(path("in/sub"));
  write("in/open.obj", obj_text(test::without_faces(test::unit_cube(), {0, 1})));
  write("in/sub/open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  const std::string glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  const bool with_glb = fs::exists(glb);
  if (with_glb) fs::copy_file(glb, path("in/sub/box.glb"));
  CommandResult r = run("check " + path("in") + " --repair " + path("out") + " --brief");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  for (const char* made : {"out/open.obj", "out/sub/open.off"}) {
    EXPECT_TRUE(fs::is_regular_file(path(made))) << made;
    EXPECT_NE(r.out.find(path(made) + ": "), std::string::npos) << r.out;
  }
  if (with_glb) {
    EXPECT_TRUE(fs::is_regular_file(path("out/sub/box.glb.obj")));
  }
  EXPECT_NE(r.err.find("umbra check: repaired " + std::string(with_glb ? "3" : "2") + " meshes into " + path("out") + ": " +
                       (with_glb ? "3" : "2") + " closed 2-manifolds, 0 not, 0 failed\n"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read(path("in/open.obj")), obj_text(test::without_faces(test::unit_cube(), {0, 1})));  // the inputs untouched
  r = run("check " + path("in") + " --repair " + path("fixed.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra check: --repair " + path("fixed.obj") + " names a mesh file, but several meshes are repaired each into a "
                   "folder: name a folder (\"" + path("fixed.obj") + "/\" makes one of that name)\n(see umbra check --help)\n");
}

// CGAL's fold.off: its one hole's faired patch bends through the fold, 11
// crossing pairs where the file had none, which no union resolves; the
// repair once kept it and called the pairs "left". A fill that crosses the
// mesh is no repair: the border's least-area triangulation, flat, closes
// it without a crossing, and the repair says so.
TEST_F(CheckCommand, RepairRefusesAFillThatCrossesTheMesh) {
  const std::string fold = std::string(UMBRA_CGAL_DATA) + "/meshes/fold.off";
  ASSERT_NE(run("check --brief " + fold).out.find("(10 border edges in 1 hole)"), std::string::npos);
  const CommandResult r = run("check " + fold + " --repair " + path("out.off") + " --brief");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(": closed 2-manifold: casts its shadow from silhouette edges"), std::string::npos) << r.out;
  const CommandResult said = run("check " + fold + " --repair " + path("again.off"));
  EXPECT_NE(said.out.find("(1 flat, by the border's least-area triangulation: faired, the patch crossed the mesh)"), std::string::npos)
      << said.out;
  EXPECT_EQ(said.out.find("pairs of triangles that cross"), std::string::npos) << said.out;
}

// A shell that crosses only itself (a prism over a bow tie, its small lobe
// inside out) has no sound inside to keep: left as it is, and said why.
TEST_F(CheckCommand, RepairLeavesAShellThatCrossesItselfAndSaysWhy) {
  const std::string input = write("in.obj", obj_text(test::bow_tie_prism()));
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("pairs of triangles that cross: a closed component crosses itself, where which side is inside is unclear\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 closed component crosses faces: which way they face is undecided"), std::string::npos) << r.out;
}

TEST_F(CheckCommand, RepairFillsASquareHoleFlat) {
  // The cube without its top's two triangles: a planar hole of 4 edges, as
  // large as the faces round it, filled with 2 triangles and nothing to fair.
  const std::string input = write("in.obj", obj_text(test::without_faces(test::unit_cube(), {4, 5})));
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  filled 1 hole with 2 triangles, refined and faired to the surface round them\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("verdict            closed 2-manifold"), std::string::npos) << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.obj")), glm::dvec3(0.5)), 1.0, 1e-12);
}

TEST_F(CheckCommand, RepairFillsATriangularHoleWithItsTriangle) {
  const std::string input = write("in.obj", obj_text(test::without_faces(test::tetrahedron(), {2})));
  const CommandResult r = run("check " + input + " --repair " + path("out.off"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  filled 1 hole with 1 triangle,"), std::string::npos) << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.off")), glm::dvec3(0.25)), 1.0 / 6.0, 1e-12);
}

TEST_F(CheckCommand, RepairFillsALargePlanarHoleAndACurvedOne) {
  // A prism on a 64-gon with no top: a planar hole of 64 edges, refined
  // (its triangles would be far larger than the walls') and faired.
  std::vector<glm::dvec2> circle;
  for (int k = 0; k < 64; ++k) circle.push_back({std::cos(k * 6.283185307179586 / 64), std::sin(k * 6.283185307179586 / 64)});
  std::vector<size_t> top;
  for (size_t k = 1; k < 2 * 62; k += 2) top.push_back(k);
  const std::string can = write("can.obj", obj_text(test::without_faces(test::prism(circle, 0.0, 1.0), top)));
  CommandResult r = run("check " + can + " --repair " + path("can-out.obj"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  filled 1 hole with "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("closed, chi 2, genus 0, outward"), std::string::npos) << r.out;
  // A sphere of 16 rings and 32 meridians without the 32 triangles round
  // its north pole: the faired patch stands in for the cap, within 1% of the
  // whole sphere's volume.
  const PolygonSoup sphere = test::uv_sphere(16, 32);
  std::vector<size_t> cap;
  for (size_t j = 0; j < 32; ++j) cap.push_back(j * 16);
  const std::string open_sphere = write("sphere.obj", obj_text(test::without_faces(sphere, cap)));
  r = run("check " + open_sphere + " --repair " + path("sphere-out.obj"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  filled 1 hole with "), std::string::npos) << r.out;
  const double whole = test::signed_volume(sphere, glm::dvec3(0.0));
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("sphere-out.obj")), glm::dvec3(0.0)), whole, 0.01 * whole);
}

// The unit cube as STL writes it, each triangle with its own three points,
// every copy of a corner off from the others by up to 1e-7: nothing merges
// but equal points, so the check sees 12 loose triangles; within 1e-6 the
// copies are one point and the cube is whole again.
TEST_F(CheckCommand, RepairMergesPointsWithinTheTolerance) {
  const PolygonSoup cube = test::unit_cube();
  std::vector<glm::dvec3> points;
  std::vector<test::Face> faces;
  for (size_t f = 0; f < cube.polygon_count(); ++f) {
    test::Face face;
    for (size_t k = 0; k < 3; ++k) {
      const double off = 1e-7 * double((f * 3 + k) % 5) / 4.0;  // 0 to 1e-7, differing between copies
      face.push_back(uint32_t(points.size()));
      points.push_back(cube.points[cube.polygon(f)[k]] + glm::dvec3(off, -off, off));
    }
    faces.push_back(face);
  }
  const std::string input = write("in.obj", obj_text(test::make_soup(points, faces)));
  CommandResult r = run("check " + input + " --repair " + path("exact.obj"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("components         12 (0 closed)"), std::string::npos) << r.out;
  r = run("check " + input + " --repair " + path("out.obj") + " --merge-tolerance 1e-6 --solid");
  EXPECT_EQ(r.status, 0) << r.out;
  // The copies that are not equal to another, less the cube's 8 corners.
  std::set<std::array<double, 3>> distinct;
  for (const glm::dvec3& p : points) distinct.insert({p.x, p.y, p.z});
  EXPECT_NE(r.out.find("  merged " + std::to_string(distinct.size() - 8) + " vertices into another within 1e-06 (--merge-tolerance)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  solid              yes\n"), std::string::npos) << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.obj")), glm::dvec3(0.5)), 1.0, 1e-6);
  EXPECT_EQ(run("check " + input + " --merge-tolerance 1e-6").err,
            "umbra check: --merge-tolerance says which points --repair merges: give --repair OUT\n(see umbra check --help)\n");
  EXPECT_EQ(run("check " + input + " --repair " + path("x.obj") + " --merge-tolerance 0").err,
            "umbra check: --merge-tolerance must be a distance above 0, got \"0\"\n(see umbra check --help)\n");
}

TEST_F(CheckCommand, RepairLeavesAHoleLargerThanAskedAndSaysHowToFillIt) {
  const std::string input = write("in.obj", obj_text(test::without_faces(test::unit_cube(), {4, 5})));
  const CommandResult r = run("check " + input + " --repair " + path("out.obj") + " --max-hole-edges 3");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("  left 1 hole of more than 3 edges open (the largest has 4; --max-hole-edges 4 fills it)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("(4 border edges in 1 hole)"), std::string::npos) << r.out;
  EXPECT_EQ(run("check " + input + " --max-hole-edges 3").err,
            "umbra check: --max-hole-edges says which holes --repair fills: give --repair OUT\n(see umbra check --help)\n");
}

// Two triangular holes that meet at one corner of the cube: once the point's
// two fans are split apart, one border runs through both copies of it. It
// is cut there into its two lobes, each filled with its triangle, and the
// corner's fans meet again: the whole cube, to its exact volume.
TEST_F(CheckCommand, RepairFillsAHoleWhoseBorderTouchesItselfLobeByLobe) {
  const PolygonSoup cube = test::unit_cube();
  const auto corners = [&](size_t f) { return std::set<uint32_t>(cube.polygon(f), cube.polygon(f) + 3); };
  size_t other = 1;
  for (; other < cube.polygon_count(); ++other) {
    std::vector<uint32_t> shared;
    const std::set<uint32_t> a = corners(0), b = corners(other);
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
    if (shared.size() == 1) break;
  }
  ASSERT_LT(other, cube.polygon_count());
  const std::string input = write("in.obj", obj_text(test::without_faces(cube, {0, other})));
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("  filled 1 hole with 2 triangles, refined and faired to the surface round them (2 lobes of holes whose "
                       "border passes twice through a point, each filled on its own)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  solid              yes\n"), std::string::npos) << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.obj")), glm::dvec3(0.5)), 1.0, 1e-12);
}

// CGAL's elephant with 171 holes, many meeting at a point: every one filled,
// and the elephant is a solid again, of the genus of CGAL's whole elephant.
TEST_F(CheckCommand, RepairMakesCgalsElephantWithHolesASolid) {
  const std::string input = std::string(UMBRA_CGAL_DATA) + "/meshes/elephant-with-holes.off";
  const CommandResult r = run("check " + input + " --repair " + path("out.off") + " --solid");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("  border             0 edges in 0 loops\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("closed, chi -4, genus 3, outward"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  solid              yes\n"), std::string::npos) << r.out;
}

// A CAD part from Debian's Open CASCADE data with two holes of 3 edges
// (admesh's repair: "Facets added 2"): both filled, and it is closed.
TEST_F(CheckCommand, RepairClosesTheHolesOfARealCadPart) {
  const std::string input = "/usr/share/opencascade/data/stl/TR12J_OCC64K.stl";
  const CommandResult r = run("check " + input + " --repair " + path("out.stl"));
  EXPECT_NE(r.out.find("  filled 2 holes with 2 triangles,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  border             0 edges in 0 loops\n"), std::string::npos) << r.out;
  // Its one shell crosses itself at 6 pairs of faces: an autorefinement
  // tried on it kept a sliver of 1.7e-05 of its 8.7e+06, so it is not tried.
  EXPECT_NE(r.out.find("  left the 6 pairs of triangles that cross: a closed component crosses itself, where which side is inside is "
                       "unclear\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("67500 faces"), std::string::npos) << r.out;
}

TEST_F(CheckCommand, RepairRefusesToOverwriteItsInputOrTakeTwoMeshes) {
  const std::string input = write("in.obj", obj_text(test::tetrahedron()));
  const CommandResult same = run("check " + input + " --repair " + input);
  EXPECT_EQ(same.status, 2);
  EXPECT_EQ(same.err, "umbra check: --repair would overwrite its input \"" + input +
                          "\"; name another file\n(see umbra check --help)\n");
  const CommandResult alias = run("check " + input + " --repair " + folder_.string() + "/./in.obj");
  EXPECT_EQ(alias.status, 2);
  const CommandResult two = run("check " + input + " " + input + " --repair " + path("x.obj"));
  EXPECT_EQ(two.status, 2);
  EXPECT_EQ(two.err, "umbra check: --repair " + path("x.obj") + " names a mesh file, but several meshes are repaired each into a "
                     "folder: name a folder (\"" + path("x.obj") + "/\" makes one of that name)\n(see umbra check --help)\n");
  // Into the folder they are read from: each copy would overwrite its mesh.
  fs::create_directories(path("meshes"));
  write("meshes/a.obj", obj_text(test::tetrahedron()));
  const CommandResult into_itself = run("check " + path("meshes") + " --repair " + path("meshes"));
  EXPECT_EQ(into_itself.status, 2);
  EXPECT_EQ(into_itself.err, "umbra check: --repair would overwrite its input \"" + path("meshes/a.obj") +
                                 "\"; name another folder\n(see umbra check --help)\n");
  EXPECT_EQ(read(path("meshes/a.obj")), obj_text(test::tetrahedron()));
  const CommandResult format = run("check " + input + " --repair " + path("x.dae"));
  EXPECT_EQ(format.status, 2);
  EXPECT_FALSE(fs::exists(path("x.obj")));
  // glTF is read but not written: refused before any work.
  for (const char* name : {"x.glb", "x.gltf"}) {
    const CommandResult unwritable = run("check " + input + " --repair " + path(name));
    EXPECT_EQ(unwritable.status, 2) << name;
    EXPECT_EQ(unwritable.out, "") << name;
    EXPECT_EQ(unwritable.err, "umbra check: --repair needs an output ending in " + mesh_format_extensions(true) + ", got \"" + path(name) +
                                  "\"\n(see umbra check --help)\n");
    EXPECT_FALSE(fs::exists(path(name))) << name;
  }
}

// assimp's spider: 5 textured materials, 6 holes. The repaired OBJ names
// its library and copies of its maps beside it, and reads them back with no
// warning, every corner at an input point with the input's coordinates there.
TEST_F(CheckCommand, RepairOfATexturedObjKeepsItsMaterialsAndMaps) {
  const std::string spider = "/usr/share/assimp/models/OBJ/spider.obj";
  if (!fs::exists(spider)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const CommandResult r = run("check " + spider + " --repair " + path("fixed.obj"));
  EXPECT_NE(r.out.find("  filled 6 holes with "), std::string::npos) << r.out << r.err;
  EXPECT_EQ(r.out.find("left out"), std::string::npos) << r.out;
  for (const char* companion : {"fixed.mtl", "fixed.SpiderTex.jpg", "fixed.drkwood2.jpg", "fixed.engineflare1.jpg",
                                "fixed.wal67ar_small.jpg", "fixed.wal69ar_small.jpg"})
    EXPECT_TRUE(fs::exists(path(companion))) << companion;
  const PolygonSoup in = read_polygon_soup(spider);
  const PolygonSoup out = read_polygon_soup(path("fixed.obj"));
  EXPECT_TRUE(out.warnings.empty()) << out.warnings[0].message;
  ASSERT_EQ(out.materials.size(), 5u);
  for (const SoupMaterial& m : out.materials) EXPECT_TRUE(m.texture) << m.name;
  std::set<std::tuple<double, double, double, float, float>> input_corners;
  std::set<std::tuple<double, double, double>> input_points;
  for (size_t c = 0; c < in.corners.size(); ++c) {
    const glm::dvec3 p = in.points[in.corners[c]];
    input_corners.insert({p.x, p.y, p.z, in.corner_uvs[c].x, in.corner_uvs[c].y});
    input_points.insert({p.x, p.y, p.z});
  }
  ASSERT_EQ(out.corner_uvs.size(), out.corners.size());
  size_t at_input_points = 0;
  for (size_t c = 0; c < out.corners.size(); ++c) {
    const glm::dvec3 p = out.points[out.corners[c]];
    if (!input_points.count({p.x, p.y, p.z})) continue;  // a point that filling a hole added
    ++at_input_points;
    EXPECT_TRUE(input_corners.count({p.x, p.y, p.z, out.corner_uvs[c].x, out.corner_uvs[c].y})) << "corner " << c;
  }
  EXPECT_GT(at_input_points, out.corners.size() / 2);
}

// A map the input names but that cannot be read is said, as render says
// it: the repaired library has no map to name.
TEST_F(CheckCommand, RepairSaysWhichMapItCouldNotRead) {
  const std::string input = write("in.obj", "mtllib in.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nusemtl a\n"
                                            "f 1/1 3/1 2/1\nf 1/1 2/1 4/1\nf 2/1 3/1 4/1\nf 1/1 4/1 3/1\n");
  write("in.mtl", "newmtl a\nKd 1 0 0\nmap_Kd missing.png\n");
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, input + ":1: warning: material \"a\"'s texture map \"" + path("missing.png") +
                       "\": does not exist: its faces take the material's Kd colour\n");
  EXPECT_EQ(read(path("out.mtl")), "# materials of out.obj, written by umbra check --repair\n\nnewmtl a\nKd 1 0 0\nKs 0 0 0\nNs 32\n");
}

TEST_F(CheckCommand, RepairNeverOverwritesAMaterialLibraryItDidNotWrite) {
  const std::string input = write("in.obj", "mtllib out.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl red\n"
                                            "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  const std::string library = write("out.mtl", "newmtl red\nKd 1 0 0\n");
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, library + ": the repair would overwrite this material library, which umbra did not write: name the output otherwise\n");
  EXPECT_EQ(read(library), "newmtl red\nKd 1 0 0\n");
  EXPECT_FALSE(fs::exists(path("out.obj")));
  // A library that an earlier repair wrote is replaced.
  ASSERT_EQ(run("check " + input + " --repair " + path("other.obj")).status, 0);
  ASSERT_EQ(run("check " + input + " --repair " + path("other.obj")).status, 0);
  EXPECT_EQ(read_polygon_soup(path("other.obj")).materials.at(0).diffuse, glm::dvec3(1, 0, 0));
}

// A map's copy beside the repaired OBJ (OUTSTEM.MAPNAME) once overwrote
// whatever file had that name, where a material library is refused.
TEST_F(CheckCommand, RepairNeverOverwritesAFileWithAMapsCopy) {
  fs::create_directories(path("in"));
  fs::create_directories(path("out"));
  Image map(1, 1, 3);
  map.at(0, 0, 0) = 255;
  write_png(map, path("in/wood.png"));
  write("in/m.mtl", "newmtl a\nmap_Kd wood.png\n");
  const std::string input = write("in/m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nusemtl a\n"
                                              "f 1/1 3/1 2/1\nf 1/1 2/1 4/1\nf 2/1 3/1 4/1\nf 1/1 4/1 3/1\n");
  const std::string theirs = write("out/x.wood.png", "somebody's picture");
  CommandResult r = run("check " + input + " --repair " + path("out/x.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, theirs + ": the repair would overwrite this file, which is not material \"a\"'s texture map, with a copy of it: "
                            "name the output otherwise\n");
  EXPECT_EQ(read(theirs), "somebody's picture");
  EXPECT_FALSE(fs::exists(path("out/x.obj")));
  // An earlier repair's copy, the same bytes, is no obstacle.
  fs::remove(theirs);
  ASSERT_EQ(run("check " + input + " --repair " + path("out/x.obj")).status, 0);
  r = run("check " + input + " --repair " + path("out/x.obj"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(theirs), read(path("in/wood.png")));
}

// A face drawn round a hole as one keyhole polygon (the outline, a bridge
// in, the hole, the bridge back) passes twice through the bridge's points:
// split into its triangles, as the check reads it, not dropped.
TEST_F(CheckCommand, RepairSplitsAKeyholeFaceIntoItsTriangles) {
  // A 3 x 3 square with a 1 x 1 hole in the middle, bridged at (0, 0)-(1, 1).
  const std::string input = write("keyhole.obj", "v 0 0 0\nv 3 0 0\nv 3 3 0\nv 0 3 0\nv 1 1 0\nv 1 2 0\nv 2 2 0\nv 2 1 0\n"
                                                 "f 1 2 3 4 1 5 6 7 8 5\n");
  const CommandResult r = run("check " + input + " --repair " + path("out.obj") + " --max-hole-edges 0");
  EXPECT_NE(r.out.find("  split 1 face that passes more than once through a point into 8 triangles\n"), std::string::npos) << r.out << r.err;
  const PolygonSoup out = read_polygon_soup(path("out.obj"));
  EXPECT_EQ(out.polygon_count(), 8u);
  EXPECT_DOUBLE_EQ(test::area(out), 8.0);
}

// A unit cube whose top is split in two at x = 0.5, the sides left whole: a
// point lies on each side's top edge (a T-junction), and the crack between
// them is a hole with no area that no patch fills. Snapped onto the edge
// and stitched, the cube is whole.
TEST_F(CheckCommand, RepairSnapsACrackWherePatchesMeetAtAPointOnAnEdge) {
  const std::string input = write("crack.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                               "v 0.5 0 1\nv 0.5 1 1\nf 1 4 3 2\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n"
                                               "f 5 9 10 8\nf 9 6 7 10\n");
  ASSERT_NE(run("check " + input).out.find("border             6 edges in 2 loops"), std::string::npos);
  const CommandResult r = run("check " + input + " --repair " + path("out.obj") + " --solid");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  snapped 2 border points onto the border across a crack and stitched 4 pairs of border edges (CGAL's "
                       "snap_borders), which closed the surface where filling alone left holes\n"),
            std::string::npos)
      << r.out;
  EXPECT_NEAR(test::signed_volume(read_polygon_soup(path("out.obj")), glm::dvec3(0.5)), 1.0, 1e-12);
}

// A flat washer (a 2 x 2 square round a 1 x 1 hole, four quads): both its
// outline and its hole stay open. Filling them would lay a second washer
// back to back with it and plug the hole.
TEST_F(CheckCommand, RepairLeavesTheHolesOfAFlatPartOpen) {
  const std::string input = write("washer.obj", "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 0.5 0.5 0\nv 1.5 0.5 0\nv 1.5 1.5 0\nv 0.5 1.5 0\n"
                                                "f 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const CommandResult r = run("check " + input + " --repair " + path("out.obj"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("  left 2 holes of flat parts open: a flat part (a panel, a sheet) has no inside to close\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  border             8 edges in 2 loops\n"), std::string::npos) << r.out;
  EXPECT_DOUBLE_EQ(test::area(read_polygon_soup(path("out.obj"))), 3.0);
}

TEST_F(CheckCommand, RepairIntoAMissingFolderFailsWithoutLeavingAFile) {
  const std::string input = write("in.obj", obj_text(test::tetrahedron()));
  const CommandResult r = run("check " + input + " --repair " + path("no/such/out.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra check: --repair " + path("no/such/out.obj") + ": there is no folder \"" + path("no/such") +
                       "\" to write it in\n(see umbra check --help)\n");
  EXPECT_FALSE(fs::exists(path("no")));
  // A repair that is written leaves no temporary file beside it.
  ASSERT_EQ(run("check " + input + " --repair " + path("out.obj")).status, 0);
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder_)) ++files;
  EXPECT_EQ(files, 4u);  // in.obj, out.obj and the command's out.txt and err.txt
}

TEST_F(CheckCommand, HelpAndUsageErrors) {
  const CommandResult help = run("check --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_EQ(help.out.rfind("usage: umbra check PATH...", 0), 0u);
  const CommandResult none = run("check");
  EXPECT_EQ(none.status, 2);
  EXPECT_EQ(none.err, "umbra check: no mesh file given\n(see umbra check --help)\n");
  const CommandResult limit = run("check a.obj --time-limit -1");
  EXPECT_EQ(limit.status, 2);
  EXPECT_EQ(limit.err, "umbra check: --time-limit must not be negative\n(see umbra check --help)\n");
}

}  // namespace
}  // namespace umbra
