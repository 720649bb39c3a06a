// The mesh check's stages, each called on its own with values made by hand:
// what a face is, how edges group, components, fans and loops, and flips.
#include <gtest/gtest.h>

#include <numeric>

#include "mesh/check/components.hpp"
#include "mesh/check/edge_groups.hpp"
#include "mesh/check/face_classes.hpp"
#include "mesh/check/face_flips.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

using namespace umbra::test;

FaceClasses classes_of(const PolygonSoup& soup) { return classify_faces(soup, soup.corners, soup.points); }

TEST(CheckStages, ClassifyFacesFindsRepeatsCollinearCornersAndCopiesInAnyRotation) {
  // 0: a triangle; 1: it rotated and reversed; 2: a repeated corner; 3: three points on a line.
  const PolygonSoup soup = make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}}, {{0, 1, 2}, {2, 1, 0}, {0, 1, 1}, {0, 1, 3}});
  const FaceClasses faces = classes_of(soup);
  EXPECT_EQ(faces.duplicate, (std::vector<uint8_t>{0, 1, 0, 0}));
  EXPECT_EQ(faces.duplicate_of[1], 0u);
  EXPECT_EQ(faces.repeats_vertex, (std::vector<uint8_t>{0, 0, 1, 0}));
  EXPECT_EQ(faces.collinear, (std::vector<uint8_t>{0, 0, 0, 1}));
  EXPECT_TRUE(faces.in_topology(0));
  EXPECT_FALSE(faces.in_topology(1));
  EXPECT_FALSE(faces.in_topology(2));
  EXPECT_TRUE(faces.in_topology(3));  // collinear faces stay: a closed mesh needs them
}

TEST(CheckStages, GroupEdgesCountsEachEdgesFacesAndWhichRunTheSameWay) {
  // Three triangles on the edge 0-1 (non-manifold), and a fourth wound against its neighbour across 1-2.
  const PolygonSoup soup =
      make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 1}},
                {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 2, 5}});
  const FaceClasses faces = classes_of(soup);
  EdgeGroups groups = group_edges(soup, faces, soup.points.size());
  ASSERT_FALSE(groups.edges.empty());
  EXPECT_EQ(groups.edges[0].a, 0u);
  EXPECT_EQ(groups.edges[0].b, 1u);
  EXPECT_EQ(groups.edges[0].uses, 3u);
  EXPECT_EQ(groups.on_non_manifold_edge[0] + groups.on_non_manifold_edge[1], 2);
  // Faces 0 and 3 both run 1 -> 2: one inconsistent edge, named by the earlier face.
  EXPECT_EQ(groups.inconsistent_edge_faces, std::vector<uint32_t>{0});
  size_t border = 0;
  for (const EdgeRun& e : groups.edges) border += e.uses == 1;
  // 0-1 (three faces), 1-2 (two), and seven border edges: 0-2, 0-3, 1-3, 0-4, 1-4, 1-5, 2-5.
  EXPECT_EQ(groups.edges.size(), 9u);
  EXPECT_EQ(border, 7u);
}

TEST(CheckStages, ComponentsFansAndLoopsOfTwoBowlsTouchingAtAVertex) {
  // Two open pyramids (4 side faces each, no base) whose apexes are the same vertex.
  const PolygonSoup soup = make_soup(
      {{0, 0, 0}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}},
      {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {0, 6, 5}, {0, 7, 6}, {0, 8, 7}, {0, 5, 8}});
  const FaceClasses faces = classes_of(soup);
  EdgeGroups groups = group_edges(soup, faces, soup.points.size());
  const ComponentLabels labels = label_components(faces, groups);
  ASSERT_EQ(labels.reports.size(), 2u);  // faces that touch only at a vertex are separate components
  EXPECT_EQ(labels.of_face, (std::vector<uint32_t>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(labels.reports[0].faces, 4u);
  EXPECT_EQ(labels.reports[0].border_edges, 4u);
  const VertexFans fans = find_vertex_fans(soup, faces, groups, labels, soup.points.size());
  EXPECT_EQ(fans.non_manifold_vertices, std::vector<uint32_t>{0});  // the shared apex: two fans
  EXPECT_EQ(fans.vertices, (std::vector<size_t>{5, 5}));            // the apex counts in both
  EXPECT_EQ(fans.non_manifold, (std::vector<uint8_t>{0, 0}));        // but each component holds one fan of it
  EXPECT_EQ(fans.topology_vertices, 9u);
  const BorderLoops loops = count_border_loops(groups, labels, soup.points.size());
  EXPECT_EQ(loops.loops, 2u);
  EXPECT_EQ(loops.per_component, (std::vector<size_t>{1, 1}));
}

TEST(CheckStages, FacesToFlipAreTheSmallerParityClassAndTurnTheirTriangles) {
  const PolygonSoup soup = reversed(unit_cube(), {3, 8});
  const FaceClasses faces = classes_of(soup);
  EdgeGroups groups = group_edges(soup, faces, soup.points.size());
  const ComponentLabels labels = label_components(faces, groups);
  const std::vector<uint8_t> flip = faces_to_flip(faces, groups.flips, labels.of_face, labels.conflict);
  std::vector<uint8_t> expected(12, 0);
  expected[3] = expected[8] = 1;
  EXPECT_EQ(flip, expected);
  FaceTriangles triangles = triangulate_faces(soup, faces, soup.points);
  ASSERT_EQ(triangles.triangles.size(), 12u);
  const auto before = triangles.triangles[3];
  turn_flipped(triangles, flip);
  EXPECT_EQ(triangles.triangles[3], (std::array<uint32_t, 3>{before[0], before[2], before[1]}));
  EXPECT_EQ(triangles.triangles[0], triangulate_faces(soup, faces, soup.points).triangles[0]);
}

}  // namespace
}  // namespace umbra
