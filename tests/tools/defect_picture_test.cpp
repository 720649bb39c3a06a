// umbra check --picture (tools/defect_picture.hpp): each defect drawn in its
// colour where the report's positions put it, and the command's output.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <string>

#include "mesh/check/mesh_check.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/tools/command_fixture.hpp"
#include "tools/defect_picture.hpp"

namespace umbra {
namespace {

using namespace umbra::test;

// In an OFF file (+y up): a horizontal and a vertical square crossing
// through both their centres (self-intersecting, and their sides border
// edges); three quads on one edge at x = 2 (a non-manifold edge); two
// triangles meeting at (-2.5, 0.5, 0) (a non-manifold vertex); a cube of
// quads with its top (+y) turned in (a face to flip).
const char* const kDefects =
    "OFF\n"
    "29 13 0\n"
    "-1 0.5 -1\n"
    "1 0.5 -1\n"
    "1 0.5 1\n"
    "-1 0.5 1\n"
    "-1 0 0\n"
    "1 0 0\n"
    "1 1 0\n"
    "-1 1 0\n"
    "2 0 0\n"
    "2 1 0\n"
    "3 0 0\n"
    "3 1 0\n"
    "2 0 1\n"
    "2 1 1\n"
    "2 0 -1\n"
    "2 1 -1\n"
    "-2.5 0.5 0\n"
    "-3 0 0\n"
    "-3 1 0\n"
    "-2 0 0\n"
    "-2 1 0\n"
    "4 0 -0.5\n"
    "5 0 -0.5\n"
    "4 1 -0.5\n"
    "5 1 -0.5\n"
    "4 0 0.5\n"
    "5 0 0.5\n"
    "4 1 0.5\n"
    "5 1 0.5\n"
    "4 0 1 2 3\n"
    "4 4 5 6 7\n"
    "4 8 9 11 10\n"
    "4 8 12 13 9\n"
    "4 8 14 15 9\n"
    "3 16 17 18\n"
    "3 16 19 20\n"
    "4 21 23 24 22\n"
    "4 25 26 28 27\n"
    "4 21 22 26 25\n"
    "4 24 28 27 23\n"
    "4 21 25 27 23\n"
    "4 22 24 28 26\n";

class DefectPictureTest : public CommandTest {
 protected:
  std::string write_mesh() const {
    const std::string p = path("defects.off");
    std::ofstream(p) << kDefects;
    return p;
  }
};

// The colour at `p` (x, y in pixels), as an RGB triple.
std::array<int, 3> colour_at(const Image& image, const glm::dvec3& p) {
  const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

TEST_F(DefectPictureTest, EachDefectIsDrawnInItsColourWhereTheReportPutsIt) {
  const PolygonSoup soup = read_polygon_soup(write_mesh());
  CheckOptions every;
  every.max_examples = SIZE_MAX;
  const MeshReport report = check_mesh(soup, every);
  ASSERT_EQ(report.non_manifold_edges, 1u);
  ASSERT_EQ(report.non_manifold_vertices, 1u);
  ASSERT_EQ(report.self_intersections.face_pairs, 1u);
  ASSERT_EQ(report.faces_to_flip, 1u);
  ASSERT_GT(report.border_edges, 0u);
  const DefectPicture picture(soup, report, "+y", 800, 800);
  const Image image = picture.draw(HeadlessGl::kAuto);

  // The vertical square's top side, from (-1, 1, 0) to (1, 1, 0), a border edge: red.
  const auto top = std::find_if(report.examples.border_edges.begin(), report.examples.border_edges.end(), [](const ElementPair& e) {
    return e.first.at.y == 1.0 && e.second.at.y == 1.0 && e.first.at.z == 0.0 && e.second.at.z == 0.0 &&
           std::abs(e.first.at.x) == 1.0 && std::abs(e.second.at.x) == 1.0;
  });
  ASSERT_NE(top, report.examples.border_edges.end());
  const auto red = colour_at(image, picture.project((top->first.at + top->second.at) / 2.0));
  EXPECT_GT(red[0], red[1] + 60);
  EXPECT_GT(red[0], red[2] + 60);
  const ElementPair& fin = report.examples.non_manifold_edges.front();
  EXPECT_EQ(fin.first.at.x, 2.0);
  const auto blue = colour_at(image, picture.project((fin.first.at + fin.second.at) / 2.0));
  EXPECT_GT(blue[2], blue[0] + 60);
  EXPECT_GT(blue[2], blue[1] + 60);
  EXPECT_EQ(report.examples.non_manifold_vertices.front().at, glm::dvec3(-2.5, 0.5, 0.0));
  const auto magenta = colour_at(image, picture.project(report.examples.non_manifold_vertices.front().at));
  EXPECT_GT(magenta[0], magenta[1] + 60);
  EXPECT_GT(magenta[2], magenta[1] + 60);
  // Both squares' centre, on their crossing: orange whichever is seen.
  const auto& crossing = report.examples.self_intersections.front();
  EXPECT_EQ(crossing.first.at, glm::dvec3(0.0, 0.5, 0.0));
  const auto orange = colour_at(image, picture.project(crossing.first.at));
  EXPECT_GT(orange[0], orange[2] + 60);
  EXPECT_GT(orange[1], orange[2] + 20);
  EXPECT_EQ(report.examples.faces_to_flip.front().at, glm::dvec3(4.5, 1.0, 0.0));
  const auto teal = colour_at(image, picture.project(report.examples.faces_to_flip.front().at));
  EXPECT_GT(teal[1], teal[0] + 60);
  EXPECT_GT(teal[2], teal[0] + 60);
  // Away from every mark, the surface's own grey.
  const auto plain = colour_at(image, picture.project({4.5, 0.5, 0.5}));  // the cube's front (+z in the file is -y staged), no defect
  EXPECT_LT(std::abs(plain[0] - plain[2]), 12);
}

TEST_F(DefectPictureTest, TheCommandWritesThePictureBesideItsReport) {
  const std::string mesh = write_mesh();
  const CommandResult r = run("check " + mesh + " --json --picture " + path("defects.png"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("\"at\":["), std::string::npos) << r.out;  // the report's positions
  EXPECT_EQ(r.err, "umbra check: drew the defects of " + mesh + " to " + path("defects.png") + "\n");
  std::ifstream png(path("defects.png"), std::ios::binary);
  std::string signature(8, '\0');
  png.read(signature.data(), 8);
  EXPECT_EQ(signature, "\x89PNG\r\n\x1a\n");
}

TEST_F(DefectPictureTest, AFolderGetsAPictureForEachMeshNamedAsRenderNamesThem) {
  fs::create_directories(path("meshes/sub"));
  std::ofstream(path("meshes/sub/defects.off")) << kDefects;
  std::ofstream(path("meshes/tetra.off")) << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const CommandResult r = run("check --brief " + path("meshes") + " --picture " + path("pictures"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(fs::is_regular_file(path("pictures/sub/defects.off.png")));
  EXPECT_TRUE(fs::is_regular_file(path("pictures/tetra.off.png")));  // a closed mesh too: nothing marked, its verdict in the legend
  // 24 triangles: 2 squares and 3 fins of 2, the bow tie's 2, the cube's 12; 6 components, the bow tie's two
  // triangles apart; 23 border edges: 4 on each square, 3 on each fin, 3 on each triangle of the bow tie.
  EXPECT_EQ(r.out, path("meshes/sub/defects.off") + ": OFF, 24 triangles, 6 components: not a closed 2-manifold (23 border "
                       "edges in 6 holes, 1 non-manifold edge, 1 non-manifold vertex, inconsistent orientation (1 face to flip), 1 "
                       "self-intersecting face pair): shadow from silhouette edges for its 1 closed component (once the renderer flips "
                       "those faces), from an edge-multiplicity volume for the other 5\n" +
                       path("meshes/tetra.off") + ": OFF, 4 triangles, 1 component: closed 2-manifold: casts its shadow from silhouette edges\n");
}

// The render's camera options turn the picture's camera: from below
// (--camera-elevation -30, the floor left out, as it would hide the model),
// a cube's bottom is nearer than its top, where from the default view it is
// the other way; they are refused where no picture is drawn.
TEST_F(DefectPictureTest, TheCameraOptionsShowADefectUnderneath) {
  const PolygonSoup cube = test::unit_cube();
  const MeshReport report = check_mesh(cube);
  StageView below;
  below.camera_elevation_deg = -30.0;
  const DefectPicture above_view(cube, report, "+z", 64, 64), below_view(cube, report, "+z", 64, 64, below);
  const glm::dvec3 top(0.5, 0.5, 1.0), bottom(0.5, 0.5, 0.0);
  EXPECT_LT(above_view.project(top).z, above_view.project(bottom).z);
  EXPECT_LT(below_view.project(bottom).z, below_view.project(top).z);
  const std::string mesh = write_mesh();
  EXPECT_EQ(run("check " + mesh + " --camera-elevation -30 --camera-azimuth 200 --picture " + path("under.png")).status, 1);
  EXPECT_TRUE(fs::is_regular_file(path("under.png")));
  const CommandResult r = run("check " + mesh + " --camera-zoom 2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra check: --camera-zoom places the defect pictures' camera: give --picture or --report\n(see umbra check --help)\n");
}

// The legend's first line is the verdict's head, the words the text
// verdict starts with: it once said "not a closed 2-manifold" or "a closed
// 2-manifold" alone.
TEST(DefectPictureLegend, SaysWhatTheVerdictSays) {
  CheckOptions unsearched;
  unsearched.self_intersection_seconds = 0.0;
  PolygonSoup degenerate = test::unit_cube();  // and a triangle of a repeated corner
  degenerate.corners.insert(degenerate.corners.end(), {0, 0, 1});
  degenerate.end_polygon(0);
  for (const MeshReport& r : {check_mesh(test::unit_cube()), check_mesh(test::without_faces(test::unit_cube(), {0, 1})),
                              check_mesh(test::unit_cube(), unsearched), check_mesh(degenerate)}) {
    EXPECT_EQ(r.verdict().rfind(r.verdict_head(), 0), 0u) << r.verdict();
    EXPECT_NE(r.verdict().find(r.verdict_head() + (r.is_closed_manifold() ? ":" : " (")), std::string::npos) << r.verdict();
  }
  EXPECT_EQ(check_mesh(test::unit_cube(), unsearched).verdict_head(), "closed and consistently oriented, not known to be clean");
  EXPECT_EQ(check_mesh(degenerate).verdict_head(), "closed and consistently oriented, but not clean");
}

TEST_F(DefectPictureTest, ThePictureOptionIsRefusedWhereItCannotApply) {
  const std::string mesh = write_mesh();
  EXPECT_EQ(run("check " + folder_.string() + " --picture " + path("x.png")).err,
            "umbra check: --picture " + path("x.png") + " names a picture, but several meshes make a picture each, in a folder: "
            "name a folder (\"" + path("x.png") + "/\" makes one of that name)\n(see umbra check --help)\n");
  EXPECT_EQ(run("check " + mesh + " --picture " + path("x.gif")).status, 2);
  EXPECT_EQ(run("check " + mesh + " --picture " + mesh).status, 2);
  EXPECT_FALSE(fs::exists(path("x.png")));
  // A mesh that cannot be read: its error, and no picture.
  std::ofstream(path("broken.off")) << "OFF\n3 1 0\n0 0 0\n";
  const CommandResult broken = run("check " + path("broken.off") + " --picture " + path("x.png"));
  EXPECT_EQ(broken.status, 2);
  EXPECT_NE(broken.err.find("broken.off:"), std::string::npos) << broken.err;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

}  // namespace
}  // namespace umbra
