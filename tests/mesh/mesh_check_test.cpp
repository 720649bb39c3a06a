// check_mesh on small meshes whose every count is known by hand.
#include <limits>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

#include "mesh/check/mesh_check.hpp"
#include "mesh/check/self_intersections.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/mesh/triangle_topology_expect.hpp"

namespace umbra {
namespace {

using namespace umbra::test;

void expect_clean_closed_manifold(const MeshReport& r) {
  EXPECT_EQ(r.border_edges, 0u);
  EXPECT_EQ(r.border_loops, 0u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.non_manifold_vertices, 0u);
  EXPECT_EQ(r.duplicate_faces, 0u);
  EXPECT_EQ(r.degenerate_faces, 0u);
  EXPECT_EQ(r.inconsistent_edges, 0u);
  EXPECT_EQ(r.self_intersections.face_pairs, 0u);
  EXPECT_TRUE(r.self_intersections.complete);
  EXPECT_TRUE(r.is_closed_manifold()) << r.verdict();
  EXPECT_EQ(r.volume_kind(), VolumeKind::kSilhouette);
}

TEST(MeshCheck, TetrahedronIsAClosedGenusZeroManifoldFacingOutward) {
  const MeshReport r = check_mesh(tetrahedron());
  expect_clean_closed_manifold(r);
  EXPECT_EQ(r.vertices, 4u);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_EQ(r.triangles, 4u);
  EXPECT_EQ(r.euler_characteristic, 2);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].genus, 0);
  EXPECT_EQ(r.components[0].outward, true);
  EXPECT_EQ(r.inward_components, 0u);
  EXPECT_EQ(r.bbox_min, glm::dvec3(0.0));
  EXPECT_EQ(r.bbox_max, glm::dvec3(1.0));
  EXPECT_EQ(r.verdict(), "closed 2-manifold: casts its shadow from silhouette edges");
}

// The measures a printer asks for, worked out by hand: a cube of side 2
// encloses 8 and has an area of 24; turned inside out it encloses -8 (an
// inverted solid); a hollow cube (side 3, a cavity of side 1) encloses 26,
// its inner shell -1; an open box encloses nothing, though it has an area.
TEST(MeshCheck, VolumeAndAreaAreWhatTheShapesEnclose) {
  const MeshReport cube = check_mesh(box_triangles(glm::dvec3(-1.0), glm::dvec3(1.0)));
  ASSERT_TRUE(cube.enclosed_volume.has_value());
  EXPECT_NEAR(*cube.enclosed_volume, 8.0, 1e-12);
  EXPECT_NEAR(cube.area, 24.0, 1e-12);
  EXPECT_NEAR(*cube.components[0].enclosed_volume, 8.0, 1e-12);
  const MeshReport inward = check_mesh(all_reversed(box_triangles(glm::dvec3(-1.0), glm::dvec3(1.0))));
  EXPECT_NEAR(*inward.enclosed_volume, -8.0, 1e-12);
  EXPECT_EQ(inward.inward_components, 1u);
  const MeshReport hollow = check_mesh(hollow_cube());
  EXPECT_NEAR(*hollow.enclosed_volume, 26.0, 1e-12);
  ASSERT_EQ(hollow.components.size(), 2u);
  EXPECT_NEAR(*hollow.components[1].enclosed_volume, -1.0, 1e-12);
  EXPECT_NEAR(hollow.area, 6.0 * 9.0 + 6.0, 1e-12);
  const MeshReport open = check_mesh(without_faces(unit_cube(), {0, 1}));
  EXPECT_FALSE(open.enclosed_volume.has_value());
  EXPECT_FALSE(open.components[0].enclosed_volume.has_value());
  EXPECT_NEAR(open.area, 5.0, 1e-12);
}

// The volume admesh prints for the STL `file` (its "Volume   :" line); 0
// when it prints none.
double volume_by_admesh(const std::string& file) {
  const std::string out = testing::TempDir() + "admesh-" + std::to_string(::getpid()) + ".txt";
  if (std::system(("admesh " + file + " > " + out).c_str()) != 0) return 0.0;
  std::ifstream text(out);
  std::string line;
  double volume = 0.0;
  while (std::getline(text, line))
    if (const size_t at = line.find("Volume   :"); at != std::string::npos) volume = std::stod(line.substr(at + 10));
  std::remove(out.c_str());
  return volume;
}

// Against admesh, the STL tool a user would reach for, on its own example
// block: the volumes agree to a millionth.
TEST(MeshCheck, VolumeEqualsAdmeshsOnItsExampleBlock) {
  const std::string block = "/usr/share/doc/admesh/examples/block.stl";
  if (!std::ifstream(block) || std::system("command -v admesh > /dev/null") != 0) GTEST_SKIP() << "needs Debian's admesh";
  const double admesh_volume = volume_by_admesh(block);
  ASSERT_GT(admesh_volume, 0.0);
  const MeshReport r = check_mesh(read_polygon_soup(block));
  ASSERT_TRUE(r.enclosed_volume.has_value());
  EXPECT_NEAR(*r.enclosed_volume / admesh_volume, 1.0, 1e-6);
}

// The closed STLs in Debian's packages: the check's volume against a sum
// of the same triangles' determinants, oriented as the check orients them,
// in long double with Neumaier's compensation (exact to far below 1e-12
// here), and against admesh's. admesh
// sums in single precision (its "Volume" of Open CASCADE's TR12J_OCC.stl is
// 8714560, 3.2e-6 above the exact 8714532.25), so it is held to what a
// float sum of that many triangles can give: 1e-5.
TEST(MeshCheck, VolumeOfEveryClosedPackagedStlIsExactAndAgreesWithAdmesh) {
  const std::vector<std::string> files = {
      "/usr/share/doc/admesh/examples/block.stl",        "/usr/share/opencascade/data/stl/propeller.stl",
      "/usr/share/opencascade/data/stl/sh1.stl",         "/usr/share/opencascade/data/stl/sh2.stl",
      "/usr/share/opencascade/data/stl/shape.stl",       "/usr/share/opencascade/data/stl/TR12J_OCC.stl"};
  if (std::system("command -v admesh > /dev/null") != 0) GTEST_SKIP() << "needs Debian's admesh";
  for (const std::string& file : files) {
    if (!std::ifstream(file)) GTEST_SKIP() << "needs " << file << " (./build.sh test installs its package)";
    const PolygonSoup soup = read_polygon_soup(file);
    CheckOptions every_example;
    every_example.max_examples = SIZE_MAX;
    const MeshReport r = check_mesh(soup, every_example);
    // The volume of the faces as the check orients them: those it flips, negated.
    std::vector<int> sign(soup.polygon_count(), 1);
    for (const ElementRef& flip : r.examples.faces_to_flip) sign[flip.index] = -1;
    long double sum = 0.0L, compensation = 0.0L;
    for (size_t f = 0; f < soup.polygon_count(); ++f) {
      const glm::dvec3 a = soup.points[soup.polygon(f)[0]], b = soup.points[soup.polygon(f)[1]], c = soup.points[soup.polygon(f)[2]];
      const long double term = ((long double)a.x * ((long double)b.y * c.z - (long double)b.z * c.y) -
                                (long double)a.y * ((long double)b.x * c.z - (long double)b.z * c.x) +
                                (long double)a.z * ((long double)b.x * c.y - (long double)b.y * c.x)) * sign[f] / 6.0L;
      const long double next = sum + term;
      compensation += std::fabs(sum) >= std::fabs(term) ? (sum - next) + term : (term - next) + sum;
      sum = next;
    }
    const double exact = double(sum + compensation);
    ASSERT_TRUE(r.enclosed_volume.has_value()) << file;
    EXPECT_NEAR(*r.enclosed_volume / exact, 1.0, 1e-12) << file;

    EXPECT_NEAR(*r.enclosed_volume / volume_by_admesh(file), 1.0, 1e-5) << file;
  }
}

// A solid, as a printer needs one, and why each of these is not: a clean
// tetrahedron is; turned inside out it is a closed 2-manifold but not a
// solid; an open box, two boxes sharing an edge, a prism whose walls cross,
// and a mesh with no faces each fail for their own reason.
TEST(MeshCheck, ASolidIsClosedManifoldOrientedOutwardAndUncrossed) {
  EXPECT_TRUE(check_mesh(tetrahedron()).is_solid());
  const MeshReport inward = check_mesh(all_reversed(tetrahedron()));
  EXPECT_TRUE(inward.is_closed_manifold());
  EXPECT_EQ(inward.solid_problems(), std::vector<std::string>{"inside out (1 closed component faces inward)"});
  EXPECT_EQ(check_mesh(without_faces(unit_cube(), {0, 1})).solid_problems(), std::vector<std::string>{"open (1 hole)"});
  // Walls that cross: which way it faces is undecided, and its face pairs cross.
  const MeshReport bow_tie = check_mesh(bow_tie_prism());
  EXPECT_EQ(bow_tie.solid_problems(),
            (std::vector<std::string>{"which way 1 closed component faces is undecided",
                                      "self-intersecting (" + std::to_string(bow_tie.self_intersections.face_pairs) + " face pairs)"}));
  EXPECT_EQ(check_mesh(make_soup({{0, 0, 0}}, {})).solid_problems(), std::vector<std::string>{"no faces"});
  CheckOptions unsearched;
  unsearched.self_intersection_seconds = 0.0;
  // Unsearched, nothing shows it uncrossed, nor so which way it faces.
  EXPECT_EQ(check_mesh(tetrahedron(), unsearched).solid_problems(),
            (std::vector<std::string>{"which way 1 closed component faces is undecided", "self-intersections not searched in full"}));
}

TEST(MeshCheck, CubeOfTrianglesAndCubeOfQuadsHaveTheSameTopology) {
  const MeshReport triangles = check_mesh(unit_cube());
  const MeshReport quads = check_mesh(box_quads(glm::dvec3(0.0), glm::dvec3(1.0)));
  expect_clean_closed_manifold(triangles);
  expect_clean_closed_manifold(quads);
  EXPECT_EQ(triangles.edges, 18u);
  EXPECT_EQ(quads.edges, 12u);  // diagonals are not edges of a quad mesh
  EXPECT_EQ(quads.file_faces, 6u);
  EXPECT_EQ(quads.triangles, 12u);
  EXPECT_EQ(triangles.euler_characteristic, 2);
  EXPECT_EQ(quads.euler_characteristic, 2);
  EXPECT_EQ(quads.components[0].outward, true);
}

TEST(MeshCheck, CubeMissingAFaceHasOneHoleOfFourBorderEdges) {
  const MeshReport r = check_mesh(without_faces(unit_cube(), {4, 5}));  // the y = 0 side (quad 2)
  EXPECT_EQ(r.border_edges, 4u);
  EXPECT_EQ(r.border_loops, 1u);
  EXPECT_EQ(r.euler_characteristic, 1);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.components[0].closed);
  EXPECT_EQ(r.components[0].genus, 0);
  EXPECT_FALSE(r.components[0].outward.has_value());  // an open surface has no inside
  EXPECT_FALSE(r.is_closed_manifold());
  EXPECT_EQ(r.volume_kind(), VolumeKind::kEdgeMultiplicity);
  EXPECT_EQ(r.problems(), std::vector<std::string>{"4 border edges in 1 hole"});
  ASSERT_EQ(r.examples.border_edges.size(), 4u);
  for (const auto& [a, b] : r.examples.border_edges) {
    EXPECT_EQ(a.index & 2, 0u) << "a border vertex has y = 0";
    EXPECT_EQ(b.index & 2, 0u);
  }
}

// A face with a hole as exporters write it: the outline, a bridge in, the
// hole the other way round, the bridge out. It visits two corners twice.
TEST(MeshCheck, KeyholePolygonIsSplitIntoTheTrianglesItCovers) {
  const PolygonSoup keyhole = test::make_soup(
      {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}},
      {{0, 1, 2, 3, 0, 4, 7, 6, 5, 4}});
  const MeshAnalysis a = analyse_mesh(keyhole);
  EXPECT_EQ(a.report.degenerate_faces, 0u);
  EXPECT_EQ(a.report.triangles, 8u);
  double area = 0.0;
  for (const auto& t : a.triangles)
    area += glm::cross(a.positions[t[1]] - a.positions[t[0]], a.positions[t[2]] - a.positions[t[0]]).z / 2.0;
  EXPECT_DOUBLE_EQ(std::abs(area), 12.0);  // 4 x 4 less the 2 x 2 hole, each part once
  EXPECT_EQ(a.report.border_edges, 8u);
  EXPECT_EQ(a.report.border_loops, 2u);
  ASSERT_EQ(a.report.warnings.size(), 1u);
  EXPECT_EQ(a.report.warnings[0].line, 9);
  EXPECT_EQ(a.report.warnings[0].message, "face 0 (10 corners) visits a vertex more than once: read as 8 triangles");
}

TEST(MeshCheck, AKeyholeWhoseBridgeEndsAreEqualPointsIsSplitAlike) {
  // The same keyhole with its bridge's ends written as separate points at
  // the same place (8 and 9 repeat 0 and 4): points are merged first, so it
  // is the same polygon, not one that repeats a vertex and is dropped.
  const PolygonSoup keyhole = test::make_soup(
      {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}, {0, 0, 0}, {1, 1, 0}},
      {{0, 1, 2, 3, 8, 4, 7, 6, 5, 9}});
  const MeshAnalysis a = analyse_mesh(keyhole);
  EXPECT_EQ(a.report.degenerate_faces, 0u);
  EXPECT_EQ(a.report.triangles, 8u);
  EXPECT_EQ(a.report.border_loops, 2u);
}

TEST(MeshCheck, APolygonThatWalksRoundItsLoopAgainIsReadOnce) {
  // "f 1 2 3 4 1 2 3 4 1 2 3 4", as an exporter's test file has it: the
  // square once, its repeats said in the warning, no duplicate faces.
  const MeshAnalysis a = analyse_mesh(test::make_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}}));
  EXPECT_EQ(a.report.triangles, 2u);
  EXPECT_EQ(a.report.duplicate_faces, 0u);
  ASSERT_EQ(a.report.warnings.size(), 1u);
  EXPECT_EQ(a.report.warnings[0].message,
            "face 0 (12 corners) visits a vertex more than once: read as 2 triangles (4 without area and 4 repeats dropped)");
}

TEST(MeshCheck, TwoCubesSharingAnEdgeHaveOneNonManifoldEdge) {
  // [0,1]^3 and [1,2]x[1,2]x[0,1] share the edge x = y = 1.
  const PolygonSoup soup = combine(unit_cube(), box_triangles({1, 1, 0}, {2, 2, 1}));
  const MeshReport r = check_mesh(soup);
  EXPECT_EQ(r.merged_vertices, 2u);
  EXPECT_EQ(r.vertices, 14u);
  EXPECT_EQ(r.non_manifold_edges, 1u);
  EXPECT_EQ(r.non_manifold_vertices, 0u);  // its ends are counted with the edge
  EXPECT_EQ(r.border_edges, 0u);
  EXPECT_EQ(r.edges, 35u);
  EXPECT_EQ(r.euler_characteristic, 14 - 35 + 24);
  EXPECT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.components[0].manifold);
  EXPECT_FALSE(r.components[0].genus.has_value());
  EXPECT_EQ(r.self_intersections.face_pairs, 0u);  // touching along a shared edge is not crossing
  ASSERT_EQ(r.examples.non_manifold_edges.size(), 1u);
  const glm::dvec3 a = soup.points[r.examples.non_manifold_edges[0].first.index];
  const glm::dvec3 b = soup.points[r.examples.non_manifold_edges[0].second.index];
  EXPECT_EQ(glm::dvec2(a), glm::dvec2(1.0, 1.0));
  EXPECT_EQ(glm::dvec2(b), glm::dvec2(1.0, 1.0));
  EXPECT_EQ(r.volume_kind(), VolumeKind::kEdgeMultiplicity);
}

TEST(MeshCheck, TwoTetrahedraSharingAVertexHaveOneNonManifoldVertex) {
  // The second tetrahedron is the first mirrored through the origin.
  PolygonSoup mirrored = all_reversed(tetrahedron());
  for (glm::dvec3& p : mirrored.points) p = -p;
  const MeshReport r = check_mesh(combine(tetrahedron(), mirrored));
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  ASSERT_EQ(r.examples.non_manifold_vertices.size(), 1u);
  EXPECT_EQ(r.examples.non_manifold_vertices[0].index, 0u);
  EXPECT_EQ(r.examples.non_manifold_vertices[0].line, 1);
  // Joined only at a vertex: two components, each a closed outward sphere.
  ASSERT_EQ(r.components.size(), 2u);
  for (const ComponentReport& c : r.components) {
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.genus, 0);
    EXPECT_EQ(c.outward, true);
  }
  EXPECT_EQ(r.euler_characteristic, 7 - 12 + 8);
  EXPECT_EQ(r.self_intersections.face_pairs, 0u);
  EXPECT_EQ(r.problems(), std::vector<std::string>{"1 non-manifold vertex"});
  // The vertex is non-manifold in the mesh, but each component has one fan
  // there: each is a closed 2-manifold on its own and casts from its silhouette.
  for (const ComponentReport& c : r.components) {
    EXPECT_EQ(c.non_manifold_vertices, 0u);
    EXPECT_TRUE(c.casts_from_silhouette());
  }
  EXPECT_EQ(r.volume_kind(), VolumeKind::kSilhouette);
  EXPECT_EQ(r.verdict(), "not a closed 2-manifold (1 non-manifold vertex): still casts its shadow from silhouette edges");
}

TEST(MeshCheck, AVertexPinchedWithinAComponentKeepsItFromTheSilhouettePath) {
  const MeshReport r = check_mesh(horn_torus(8));
  EXPECT_EQ(r.border_edges, 0u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.inconsistent_edges, 0u);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  ASSERT_EQ(r.components.size(), 1u);
  const ComponentReport& c = r.components[0];
  EXPECT_EQ(c.non_manifold_edges, 0u);
  EXPECT_EQ(c.non_manifold_vertices, 1u);
  EXPECT_FALSE(c.manifold);
  EXPECT_FALSE(c.closed);
  EXPECT_TRUE(c.orientable);
  EXPECT_FALSE(c.casts_from_silhouette());
  EXPECT_EQ(r.volume_kind(), VolumeKind::kEdgeMultiplicity);
  EXPECT_EQ(r.self_intersections.face_pairs, 0u);  // the fans meet only at the centre
  EXPECT_EQ(r.verdict(), "not a closed 2-manifold (1 non-manifold vertex): shadow from an edge-multiplicity volume (exact "
                         "for any triangles)");
}

TEST(MeshCheck, ComponentsThatCastTheirShadowsDifferentWaysAreEachReported) {
  // A tetrahedron, a lone triangle beside it, and a cube with a face wound the other way.
  const PolygonSoup soup = combine(combine(tetrahedron(), make_soup({{3, 0, 0}, {4, 0, 0}, {3, 1, 0}}, {{0, 1, 2}})),
                                   reversed(box_triangles({5, 0, 0}, {6, 1, 1}), {4}));
  CheckOptions options;
  options.self_intersection_seconds = 0.0;
  const MeshReport r = check_mesh(soup, options);
  ASSERT_EQ(r.components.size(), 3u);
  EXPECT_TRUE(r.components[0].casts_from_silhouette());
  EXPECT_FALSE(r.components[1].casts_from_silhouette());
  EXPECT_TRUE(r.components[2].casts_from_silhouette());  // once that face is flipped
  EXPECT_EQ(r.silhouette_components(), 2u);
  EXPECT_EQ(r.volume_kind(), VolumeKind::kMixed);
  EXPECT_EQ(r.verdict(), "not a closed 2-manifold (3 border edges in 1 hole, inconsistent orientation (1 face to flip), "
                         "self-intersections not checked): shadow from silhouette edges for its 2 closed components (once "
                         "the renderer flips those faces), from an edge-multiplicity volume for the other 1");
  std::ostringstream json;
  r.print_json(json);
  const std::string line = json.str();
  EXPECT_NE(line.find("\"shadow_method\":\"mixed\""), std::string::npos) << line;
  const auto component_volume = [&](size_t k) {  // the k-th component's shadow_method in the JSON
    size_t at = line.find("\"component_list\"");
    for (size_t i = 0; i <= k; ++i) at = line.find("\"shadow_method\":", at + 1);
    return line.substr(at, line.find(',', at) - at);
  };
  EXPECT_EQ(component_volume(0), "\"shadow_method\":\"silhouette\"}");
  EXPECT_EQ(component_volume(1), "\"shadow_method\":\"edge-multiplicity\"}");
  EXPECT_EQ(component_volume(2), "\"shadow_method\":\"silhouette\"}]");
  // The renderer's per-triangle choice is the report's, component by component.
  EXPECT_TRUE(test::expect_triangle_topology_as_built(soup));
}

TEST(MeshCheck, OneFlippedFaceIsNamedAsTheFaceToFlip) {
  const MeshReport r = check_mesh(reversed(unit_cube(), {7}));
  EXPECT_EQ(r.inconsistent_edges, 3u);
  EXPECT_EQ(r.faces_to_flip, 1u);
  ASSERT_EQ(r.examples.faces_to_flip.size(), 1u);
  EXPECT_EQ(r.examples.faces_to_flip[0].index, 7u);
  EXPECT_EQ(r.non_orientable_components, 0u);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_TRUE(r.components[0].orientable);
  EXPECT_FALSE(r.components[0].consistently_oriented);
  EXPECT_EQ(r.components[0].outward, true);  // once the face is flipped
  EXPECT_EQ(r.problems(), std::vector<std::string>{"inconsistent orientation (1 face to flip)"});
  // The renderer flips it and casts the shadow from the silhouette.
  EXPECT_EQ(r.volume_kind(), VolumeKind::kSilhouette);
  EXPECT_EQ(r.verdict(), "not a closed 2-manifold (inconsistent orientation (1 face to flip)): casts its shadow from "
                         "silhouette edges once the renderer flips those faces");
}

TEST(MeshCheck, AHollowSolidsInnerShellFacingItsCavityIsNotInward) {
  const MeshReport right = check_mesh(test::hollow_cube());
  ASSERT_EQ(right.components.size(), 2u);
  EXPECT_EQ(right.inward_components, 0u);
  EXPECT_EQ(right.components[0].outward, true);
  EXPECT_EQ(right.components[1].outward, true);  // it faces away from the solid: into the cavity
  // The inner shell facing into the solid instead is the one that is wrong.
  const MeshReport wrong = check_mesh(test::combine(test::box_triangles(glm::dvec3(0.0), glm::dvec3(3.0)),
                                                    test::box_triangles(glm::dvec3(1.0), glm::dvec3(2.0))));
  EXPECT_EQ(wrong.inward_components, 1u);
  EXPECT_EQ(wrong.components[0].outward, true);
  EXPECT_EQ(wrong.components[1].outward, false);
  // Three nested shells: the innermost (depth 2) is solid again and faces out.
  const MeshReport three = check_mesh(test::combine(test::hollow_cube(), test::box_triangles(glm::dvec3(1.25), glm::dvec3(1.75))));
  EXPECT_EQ(three.inward_components, 0u);
}

// Which way a closed shell faces is decided only where the answer is sound:
// for a shell that crosses no face, of its own or of another shell. Shells
// that cross each other, or a shell whose walls cross, are left undecided,
// whatever the order of their faces, and never counted inward.
TEST(MeshCheck, ShellsThatCrossHaveNoDecidedFacing) {
  const PolygonSoup crossing = test::box_through_l_prism();
  for (const PolygonSoup& soup : {crossing, test::combine(test::box_triangles(glm::dvec3(1.2, 0.5, 0.2), glm::dvec3(1.8, 1.5, 0.8)),
                                                          test::prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0.0, 1.0))}) {
    const MeshReport r = check_mesh(soup);
    ASSERT_EQ(r.components.size(), 2u);
    EXPECT_GT(r.self_intersections.face_pairs, 0u);
    EXPECT_EQ(r.inward_components, 0u);
    EXPECT_EQ(r.undecided_components, 2u);
    for (const ComponentReport& c : r.components) {
      EXPECT_TRUE(c.closed);
      EXPECT_FALSE(c.outward.has_value());
    }
  }
  const MeshReport bow_tie = check_mesh(test::bow_tie_prism());
  ASSERT_EQ(bow_tie.components.size(), 1u);
  EXPECT_TRUE(bow_tie.components[0].closed);
  EXPECT_GT(bow_tie.self_intersections.face_pairs, 0u);
  EXPECT_FALSE(bow_tie.components[0].outward.has_value());
  EXPECT_EQ(bow_tie.undecided_components, 1u);
  // Without the search nothing shows that a shell is clean: undecided too.
  CheckOptions no_search;
  no_search.self_intersection_seconds = 0.0;
  const MeshReport unsearched = check_mesh(test::hollow_cube(), no_search);
  EXPECT_EQ(unsearched.undecided_components, 2u);
  EXPECT_EQ(unsearched.inward_components, 0u);
}

TEST(MeshCheck, InwardCubeIsAClosedManifoldThatSaysItFacesInward) {
  const MeshReport r = check_mesh(all_reversed(unit_cube()));
  expect_clean_closed_manifold(r);
  EXPECT_EQ(r.inward_components, 1u);
  EXPECT_EQ(r.components[0].outward, false);
  EXPECT_NE(r.verdict().find("oriented inward"), std::string::npos);
}

TEST(MeshCheck, InterpenetratingCubesCrossInSixFacePairs) {
  // [0,2]^3 and [1,3]^3: each of A's faces x, y, z = 2 crosses two of B's faces x, y, z = 1.
  const MeshReport r = check_mesh(combine(box_quads({0, 0, 0}, {2, 2, 2}), box_quads({1, 1, 1}, {3, 3, 3})));
  EXPECT_EQ(r.self_intersections.face_pairs, 6u);
  EXPECT_TRUE(r.self_intersections.complete);
  EXPECT_EQ(r.components.size(), 2u);
  EXPECT_EQ(r.border_edges + r.non_manifold_edges + r.non_manifold_vertices + r.inconsistent_edges, 0u);
  ASSERT_EQ(r.examples.self_intersections.size(), 5u);  // the first five of six
  for (const auto& [f, g] : r.examples.self_intersections) {
    EXPECT_LT(f.index, 6u);  // one face of each cube
    EXPECT_GE(g.index, 6u);
  }
  EXPECT_FALSE(r.is_closed_manifold());
  EXPECT_EQ(r.problems(), std::vector<std::string>{"6 self-intersecting face pairs"});
  // Closed and consistently oriented: the silhouette method still holds.
  EXPECT_EQ(r.volume_kind(), VolumeKind::kSilhouette);
}

TEST(MeshCheck, DegenerateFacesAreCountedAndKeptOutOfTheTests) {
  // A tetrahedron, a face that repeats a vertex, and a separate face whose
  // corners lie on a line.
  PolygonSoup soup = tetrahedron();
  soup.corners.insert(soup.corners.end(), {0, 1, 1});
  soup.end_polygon(10);
  const PolygonSoup sliver = make_soup({{5, 5, 5}, {6, 6, 6}, {7, 7, 7}}, {{0, 1, 2}});
  const MeshReport r = check_mesh(combine(soup, sliver));
  EXPECT_EQ(r.degenerate_faces, 2u);
  ASSERT_EQ(r.examples.degenerate_faces.size(), 2u);
  EXPECT_EQ(r.examples.degenerate_faces[0].index, 4u);
  EXPECT_EQ(r.examples.degenerate_faces[0].line, 10);
  EXPECT_EQ(r.examples.degenerate_faces[1].index, 5u);
  // The repeated-vertex face is left out of the topology; the sliver is an open piece.
  ASSERT_EQ(r.components.size(), 2u);
  EXPECT_TRUE(r.components[0].closed);
  EXPECT_EQ(r.components[1].border_edges, 3u);
  EXPECT_EQ(r.border_loops, 1u);
  EXPECT_EQ(r.triangles, 5u);  // the sliver stays a triangle, skipped by the exact crossing tests
  EXPECT_EQ(r.self_intersections.face_pairs, 0u);
}

TEST(MeshCheck, EveryCopyOfAFaceNamesTheFirstAndQuadsMatchInAnyRotation) {
  // Faces: 0-3 the tetrahedron, then 4 and 6 repeat face 2, 5 repeats 0; a
  // quad (7) is repeated rotated and reversed (8), and a triangle sharing its
  // smallest vertex and two more (9) is not a copy of anything.
  PolygonSoup soup = tetrahedron();
  soup.corners.insert(soup.corners.end(), {soup.corners[6], soup.corners[7], soup.corners[8]});
  soup.end_polygon(10);
  soup.corners.insert(soup.corners.end(), {soup.corners[2], soup.corners[0], soup.corners[1]});
  soup.end_polygon(11);
  soup.corners.insert(soup.corners.end(), {soup.corners[8], soup.corners[7], soup.corners[6]});
  soup.end_polygon(12);
  soup.add_point({5, 5, 5}, 13);
  soup.add_point({6, 5, 5}, 14);
  soup.add_point({6, 6, 5}, 15);
  soup.add_point({5, 6, 5}, 16);
  soup.corners.insert(soup.corners.end(), {4, 5, 6, 7});
  soup.end_polygon(17);
  soup.corners.insert(soup.corners.end(), {6, 5, 4, 7});
  soup.end_polygon(18);
  soup.corners.insert(soup.corners.end(), {4, 5, 6});
  soup.end_polygon(19);
  const MeshReport r = check_mesh(soup);
  EXPECT_EQ(r.duplicate_faces, 4u);
  ASSERT_EQ(r.examples.duplicate_faces.size(), 4u);
  std::vector<std::pair<uint32_t, uint32_t>> named;
  for (const auto& [copy, original] : r.examples.duplicate_faces) named.push_back({copy.index, original.index});
  EXPECT_EQ(named, (std::vector<std::pair<uint32_t, uint32_t>>{{4, 2}, {5, 0}, {6, 2}, {8, 7}}));
}

TEST(MeshCheck, DuplicateFaceIsNamedWithTheFaceItRepeats) {
  PolygonSoup soup = tetrahedron();
  soup.corners.insert(soup.corners.end(), {1, 0, 2});  // face 0 reversed
  soup.end_polygon(9);
  const MeshReport r = check_mesh(soup);
  EXPECT_EQ(r.duplicate_faces, 1u);
  ASSERT_EQ(r.examples.duplicate_faces.size(), 1u);
  EXPECT_EQ(r.examples.duplicate_faces[0].first.index, 4u);
  EXPECT_EQ(r.examples.duplicate_faces[0].second.index, 0u);
  // Left out of the topology, so it is reported once and not again as four non-manifold edges.
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.border_edges, 0u);
  EXPECT_EQ(r.problems(), std::vector<std::string>{"1 duplicate face"});
  EXPECT_EQ(r.volume_kind(), VolumeKind::kSilhouette);
}

TEST(MeshCheck, TorusHasGenusOne) {
  const MeshReport r = check_mesh(quad_torus(8, 6));
  expect_clean_closed_manifold(r);
  EXPECT_EQ(r.vertices, 48u);
  EXPECT_EQ(r.edges, 96u);
  EXPECT_EQ(r.euler_characteristic, 0);
  EXPECT_EQ(r.components[0].genus, 1);
  EXPECT_EQ(r.components[0].outward, true);
}

TEST(MeshCheck, MoebiusStripIsNotOrientable) {
  const MeshReport r = check_mesh(moebius_strip(12));
  EXPECT_EQ(r.non_orientable_components, 1u);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.components[0].orientable);
  EXPECT_FALSE(r.components[0].genus.has_value());
  EXPECT_EQ(r.border_loops, 1u);  // its one edge runs around twice
  EXPECT_EQ(r.border_edges, 24u);
  EXPECT_EQ(r.euler_characteristic, 0);
  EXPECT_EQ(r.volume_kind(), VolumeKind::kEdgeMultiplicity);
}

TEST(MeshCheck, BowTieOfTwoTrianglesHasANonManifoldVertex) {
  const MeshReport r = check_mesh(make_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}}));
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.components.size(), 2u);
  EXPECT_EQ(r.border_edges, 6u);
}

TEST(MeshCheck, CoincidentPointsAreMergedIntoOneVertex) {
  // The cube with each triangle's corners written out separately, as STL does.
  const PolygonSoup cube = unit_cube();
  std::vector<glm::dvec3> points;
  std::vector<Face> faces;
  for (size_t f = 0; f < cube.polygon_count(); ++f) {
    Face face;
    for (uint32_t k = 0; k < 3; ++k) {
      face.push_back(uint32_t(points.size()));
      points.push_back(cube.points[cube.polygon(f)[k]]);
    }
    faces.push_back(face);
  }
  const MeshReport r = check_mesh(make_soup(points, faces));
  expect_clean_closed_manifold(r);
  EXPECT_EQ(r.file_vertices, 36u);
  EXPECT_EQ(r.merged_vertices, 28u);
  EXPECT_EQ(r.vertices, 8u);
}

// Pairs of triangles that share a vertex or an edge, in one plane and out
// of it: which meet beyond what they share, decided case by case.
TEST(MeshCheck, NeighboursMeetBeyondWhatTheyShareOnlyWhereTheyOverlapOrTouch) {
  const auto crossing_pairs = [](const std::vector<glm::dvec3>& points, const std::vector<Face>& faces) {
    return check_mesh(make_soup(points, faces)).self_intersections.face_pairs;
  };
  const glm::dvec3 v(0, 0, 0);
  // Sharing a vertex, in the plane z = 0: sectors apart, overlapping, touching along a ray.
  EXPECT_EQ(crossing_pairs({v, {1, 0, 0}, {1, 1, 0}, {-1, 0.1, 0}, {-1, 1, 0}}, {{0, 1, 2}, {0, 3, 4}}), 0u);
  EXPECT_EQ(crossing_pairs({v, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2}, {0, 3, 4}}), 1u);
  EXPECT_EQ(crossing_pairs({v, {1, 0, 0}, {1, 1, 0}, {2, 2, 0}, {-1, 1, 0}}, {{0, 1, 2}, {0, 3, 4}}), 1u);
  // Sharing a vertex out of the plane: one pokes through the other; one stands clear of it.
  EXPECT_EQ(crossing_pairs({v, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}}, {{0, 1, 2}, {0, 3, 4}}), 1u);
  EXPECT_EQ(crossing_pairs({v, {2, 0, 0}, {0, 2, 0}, {-1, -1, 1}, {-1, 0, 1}}, {{0, 1, 2}, {0, 3, 4}}), 0u);
  // Sharing an edge: coplanar on opposite sides, coplanar folded onto each other, bent.
  EXPECT_EQ(crossing_pairs({v, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}}, {{0, 1, 2}, {1, 0, 3}}), 0u);
  EXPECT_EQ(crossing_pairs({v, {1, 0, 0}, {0.5, 1, 0}, {0.3, 2, 0}}, {{0, 1, 2}, {1, 0, 3}}), 1u);
  EXPECT_EQ(crossing_pairs({v, {1, 0, 0}, {0.5, 1, 0}, {0.5, 1, 0.001}}, {{0, 1, 2}, {1, 0, 3}}), 0u);
}

TEST(MeshCheck, TimeLimitOfZeroSkipsTheSelfIntersectionSearchAndSaysSo) {
  CheckOptions options;
  options.self_intersection_seconds = 0.0;
  const MeshReport r = check_mesh(unit_cube(), options);
  EXPECT_FALSE(r.self_intersections.checked);
  EXPECT_FALSE(r.is_closed_manifold());
  EXPECT_EQ(r.problems(), std::vector<std::string>{"self-intersections not checked"});
  EXPECT_EQ(r.volume_kind(), VolumeKind::kSilhouette);
}

TEST(MeshCheck, SelfIntersectionSearchThatHitsItsTimeLimitSaysSo) {
  CheckOptions options;
  options.self_intersection_seconds = 1e-9;  // over before the first clock check, after 1024 box pairs
  const MeshReport r = check_mesh(uv_sphere(64, 64), options);
  EXPECT_TRUE(r.self_intersections.checked);
  EXPECT_FALSE(r.self_intersections.complete);
  EXPECT_EQ(r.self_intersections.face_pairs, 0u);
  EXPECT_EQ(r.problems(), std::vector<std::string>{"self-intersection search stopped after 1e-09 s"});
  EXPECT_FALSE(r.is_closed_manifold());
  EXPECT_EQ(r.volume_kind(), VolumeKind::kSilhouette);
  EXPECT_TRUE(check_mesh(uv_sphere(64, 64)).self_intersections.complete);
}

TEST(MeshCheck, AVeryLargeTimeLimitIsNoLimit) {
  // 1e10 s is more than the clock's 64-bit nanoseconds reach from now: it
  // must not wrap round to a deadline already past.
  for (const double seconds : {9.3e9, 1e10, 1e300, std::numeric_limits<double>::infinity()}) {
    CheckOptions options;
    options.self_intersection_seconds = seconds;
    const MeshReport r = check_mesh(uv_sphere(64, 64), options);
    EXPECT_TRUE(r.self_intersections.complete) << seconds;
    EXPECT_TRUE(r.is_closed_manifold()) << seconds;
  }
}

TEST(MeshCheck, EmptyMeshHasNoFaces) {
  const MeshReport r = check_mesh(make_soup({}, {}));
  EXPECT_EQ(r.problems(), std::vector<std::string>{"no faces"});
  EXPECT_EQ(r.volume_kind(), VolumeKind::kEdgeMultiplicity);
}

TEST(MeshCheck, SelfIntersectionSearchSkipsTrianglesWithoutAPlane) {
  // Triangle 1 has collinear corners and lies across triangle 0; an exact
  // test of it would be undefined, so it is skipped, not an error.
  const std::vector<glm::dvec3> points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 0}, {0.5, 0.5, 1},
                                          {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  const SelfIntersections found =
      find_self_intersections(points, {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}, {0, 1, 2}, 10.0, 5);
  EXPECT_EQ(found.face_pairs, 0u);
  EXPECT_TRUE(found.complete);
  // The same segment as a proper triangle through triangle 0 is found.
  const SelfIntersections crossing =
      find_self_intersections(points, {{0, 1, 2}, {3, 5, 7}, {6, 7, 8}}, {0, 1, 2}, 10.0, 5);
  EXPECT_EQ(crossing.face_pairs, 1u);
  ASSERT_EQ(crossing.examples.size(), 1u);
  EXPECT_EQ(crossing.examples[0], std::make_pair(0u, 1u));
}

TEST(MeshCheck, SelfIntersectionSearchFindsEveryPairOverManyBatches) {
  // 128 parallel triangles stacked 0.005 apart, each crossed by each of 128
  // standing across the stack: 128 * 128 crossing pairs, in many batches of
  // tests (with two threads, each thread is handed several).
  const tbb::global_control two_threads(tbb::global_control::max_allowed_parallelism, 2);
  constexpr uint32_t kLayers = 128;
  std::vector<glm::dvec3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
  for (uint32_t k = 0; k < kLayers; ++k) {
    const double z = 0.005 * k, x = 0.002 * k;
    const auto first = uint32_t(points.size());
    points.insert(points.end(), {{-1, -1, z}, {1, -1, z}, {0, 1, z}, {x, 0, -1}, {x, 0.2, 2}, {x, -0.2, 2}});
    triangles.push_back({first, first + 1, first + 2});
    triangles.push_back({first + 3, first + 4, first + 5});
  }
  std::vector<uint32_t> face(triangles.size());
  for (uint32_t t = 0; t < face.size(); ++t) face[t] = t;
  const SelfIntersections whole = find_self_intersections(points, triangles, face, 10.0, 5);
  EXPECT_TRUE(whole.complete);
  EXPECT_EQ(whole.face_pairs, size_t(kLayers) * kLayers);
}

// What loading for the renderer decides about back faces
// (CheckOptions::decide_back_faces): with every shell facing out as loaded,
// the picture decides, and no search runs; a shell to turn round, or one in
// a cavity, takes the search; an open mesh, neither.
TEST(MeshCheck, TheRenderersLoadingSearchesOnlyWhereAShellWouldBeTurned) {
  CheckOptions for_rendering;
  for_rendering.self_intersection_seconds = 0.0;
  for_rendering.decide_back_faces = true;
  const MeshAnalysis clean = analyse_mesh(unit_cube(), for_rendering);
  EXPECT_EQ(clean.back_faces, BackFaces::kHiddenUnlessSeen);
  EXPECT_FALSE(clean.report.self_intersections.checked);
  // A lobe turned inside out: each shell faces out were it not to cross itself.
  EXPECT_EQ(analyse_mesh(bow_tie_prism(), for_rendering).back_faces, BackFaces::kHiddenUnlessSeen);

  const MeshAnalysis inward = analyse_mesh(all_reversed(unit_cube()), for_rendering);
  EXPECT_EQ(inward.back_faces, BackFaces::kHidden);
  EXPECT_TRUE(inward.report.self_intersections.checked);
  EXPECT_EQ(inward.report.inward_components, 1u);
  const MeshAnalysis hollow = analyse_mesh(hollow_cube(), for_rendering);
  EXPECT_EQ(hollow.back_faces, BackFaces::kDrawn);
  EXPECT_TRUE(hollow.report.self_intersections.checked);

  const MeshAnalysis opened = analyse_mesh(without_faces(unit_cube(), {4, 5}), for_rendering);
  EXPECT_EQ(opened.back_faces, BackFaces::kDrawn);
  EXPECT_FALSE(opened.report.self_intersections.checked);
  // Without the option, as umbra check loads: nothing is decided for the renderer.
  EXPECT_EQ(analyse_mesh(unit_cube()).back_faces, BackFaces::kDrawn);
}

// Random soups over a few points (so that faces share vertices and edges and
// repeat each other) and random polygons: the check finishes and its counts agree.
TEST(MeshCheck, RandomSoupsAreCheckedWithConsistentCounts) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<glm::dvec3> points;
    const int point_count = 3 + int(random() % 8);
    for (int i = 0; i < point_count; ++i)
      points.push_back(glm::dvec3(random() % 3, random() % 3, random() % 3));  // coincident and collinear points on purpose
    std::vector<Face> faces;
    const int face_count = 1 + int(random() % 12);
    for (int f = 0; f < face_count; ++f) {
      Face face(3 + random() % 3);
      for (uint32_t& v : face) v = uint32_t(random() % uint32_t(point_count));
      faces.push_back(face);
    }
    MeshReport r;
    ASSERT_NO_THROW(r = check_mesh(make_soup(points, faces))) << "trial " << trial;
    size_t faces_in_components = 0, border_edges = 0, loops = 0;
    for (const ComponentReport& c : r.components) {
      faces_in_components += c.faces;
      border_edges += c.border_edges;
      loops += c.border_loops;
      EXPECT_EQ(c.closed, c.border_edges == 0 && c.manifold);
    }
    EXPECT_LE(faces_in_components + r.duplicate_faces, r.file_faces);
    EXPECT_EQ(border_edges, r.border_edges);
    EXPECT_EQ(loops, r.border_loops);
    EXPECT_EQ(r.is_closed_manifold(), r.problems().empty());
  }
}

// The renderer takes the edge table and closed components from the check;
// they must be what a pass over the triangles alone would make, on meshes
// closed, open, flipped, inward, non-orientable, pinched and touching at a
// vertex, of triangles and of polygons, and on random soups full of repeats,
// duplicates and non-manifold edges.
TEST(MeshCheck, TriangleTopologyIsWhatASecondPassOverTheTrianglesGives) {
  const PolygonSoup bowtie = combine(tetrahedron(), tetrahedron(glm::dvec3(1.0, 0.0, 0.0)));  // vertex 1 of one is vertex 0 of the other
  for (const PolygonSoup& soup : {unit_cube(), reversed(unit_cube(), {0, 3, 7}), all_reversed(unit_cube()),
                                  triangulated(hollow_cube()), without_faces(unit_cube(), {2}), triangulated(moebius_strip(12)),
                                  bowtie, triangulated(uv_sphere(8, 12)), combine(unit_cube(), reversed(octahedron(), {1})),
                                  box_quads(glm::dvec3(0.0), glm::dvec3(1.0)), horn_torus(6), uv_sphere(6, 8)})
    EXPECT_TRUE(test::expect_triangle_topology_as_built(soup));

  std::mt19937 random(5);
  size_t given = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<glm::dvec3> points;
    const int point_count = 3 + int(random() % 8);
    for (int i = 0; i < point_count; ++i) points.push_back(glm::dvec3(random() % 3, random() % 3, random() % 3));
    std::vector<Face> faces;
    const int face_count = 1 + int(random() % 16);
    for (int f = 0; f < face_count; ++f) {
      Face face(3);
      for (uint32_t& v : face) v = uint32_t(random() % uint32_t(point_count));
      faces.push_back(face);
    }
    SCOPED_TRACE(trial);
    given += test::expect_triangle_topology_as_built(make_soup(points, faces));
  }
  EXPECT_EQ(given, 400u);
}

}  // namespace
}  // namespace umbra
