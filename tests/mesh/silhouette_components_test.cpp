// The edge table and the closed-component decision on meshes small enough to
// count by hand.
#include <gtest/gtest.h>

#include "mesh/topology/silhouette_components.hpp"
#include "mesh/topology/edge_table.hpp"

namespace umbra {
namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

// A tetrahedron on vertices 0..3 (offset by `first`), faces counter-clockwise seen from outside.
Triangles tetrahedron(uint32_t first = 0) {
  const uint32_t a = first, b = first + 1, c = first + 2, d = first + 3;
  return {{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}};
}

SilhouetteComponents components_of(const Triangles& triangles, size_t vertices) {
  return find_silhouette_components(triangles, build_edge_table(triangles, vertices), vertices);
}

Triangles operator+(Triangles a, const Triangles& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(EdgeTable, ListsEachEdgeOnceWithEveryFaceAndItsDirection) {
  // Two triangles sharing edge 1-2: 0 1 2 runs 1 -> 2, 2 1 3 runs 2 -> 1.
  const EdgeTable t = build_edge_table({{0, 1, 2}, {2, 1, 3}}, 4);
  ASSERT_EQ(t.size(), 5u);
  const std::vector<std::array<uint32_t, 2>> expected{{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}};
  EXPECT_EQ(t.vertices, expected);
  EXPECT_EQ(t.first_use, (std::vector<uint32_t>{0, 1, 2, 4, 5, 6}));
  // Edge 0-1: face 0 runs 0 -> 1 (forward). Edge 0-2: face 0 runs 2 -> 0.
  EXPECT_EQ(t.uses[0], (0u << 1) | 1u);
  EXPECT_EQ(t.uses[1], (0u << 1) | 0u);
  // Edge 1-2: face 0 forward, face 1 backward.
  EXPECT_EQ(t.uses[2], (0u << 1) | 1u);
  EXPECT_EQ(t.uses[3], (1u << 1) | 0u);
  // Edge 1-3: face 1 runs 1 -> 3. Edge 2-3: face 1 runs 3 -> 2.
  EXPECT_EQ(t.uses[4], (1u << 1) | 1u);
  EXPECT_EQ(t.uses[5], (1u << 1) | 0u);
}

TEST(SilhouetteComponents, ATetrahedronIsAClosed2Manifold) {
  const SilhouetteComponents c = components_of(tetrahedron(), 4);
  EXPECT_TRUE(c.all_cast_from_silhouette());
  EXPECT_EQ(c.silhouette_face, (std::vector<uint8_t>{1, 1, 1, 1}));
  EXPECT_EQ(c.phrase(), "closed 2-manifold");
  EXPECT_EQ(c.volume_phrase(), "silhouette volume");
}

TEST(SilhouetteComponents, ATetrahedronWithoutAFaceIsOpenWithOneHole) {
  Triangles open = tetrahedron();
  open.pop_back();
  const SilhouetteComponents c = components_of(open, 4);
  EXPECT_EQ(c.border_edges, 3u);
  EXPECT_EQ(c.border_loops, 1u);
  EXPECT_EQ(c.silhouette_components, 0u);
  EXPECT_EQ(c.phrase(), "open, 1 hole");
  EXPECT_EQ(c.volume_phrase(), "edge-multiplicity volume");
}

TEST(SilhouetteComponents, AFinOnAClosedMeshMakesANonManifoldEdge) {
  // A third face on the tetrahedron's edge 0-1 (the fin reaches vertex 4).
  const SilhouetteComponents c = components_of(tetrahedron() + Triangles{{0, 1, 4}}, 5);
  EXPECT_EQ(c.non_manifold_edges, 1u);
  EXPECT_EQ(c.border_edges, 2u);  // the fin's other two edges
  EXPECT_EQ(c.components, 1u);
  EXPECT_EQ(c.silhouette_face, (std::vector<uint8_t>(5, 0)));
  EXPECT_EQ(c.phrase(), "open, 1 hole, 1 non-manifold edge");
}

TEST(SilhouetteComponents, AFaceWoundTheOtherWayGivesThreeEdgesOfMixedWinding) {
  Triangles t = tetrahedron();
  std::swap(t[3][1], t[3][2]);
  const SilhouetteComponents c = components_of(t, 4);
  EXPECT_EQ(c.inconsistent_edges, 3u);
  EXPECT_FALSE(c.all_cast_from_silhouette());
  EXPECT_EQ(c.phrase(), "3 edges with mixed winding");
}

TEST(SilhouetteComponents, TwoTetrahedraSharingAVertexHaveANonManifoldVertexAndEachIsClosed) {
  // Vertex 0 is the apex of both; the second uses vertices 0, 4, 5, 6.
  Triangles second = tetrahedron(3);
  for (auto& tri : second)
    for (uint32_t& v : tri)
      if (v == 3) v = 0;
  const SilhouetteComponents c = components_of(tetrahedron() + second, 7);
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.non_manifold_vertices, 1u);
  // Each has one fan round the vertex: a closed 2-manifold on its own.
  EXPECT_EQ(c.silhouette_components, 2u);
  EXPECT_EQ(c.silhouette_face, std::vector<uint8_t>(8, 1));
  EXPECT_EQ(c.phrase(), "1 non-manifold vertex; 2 of 2 components closed");
}

TEST(SilhouetteComponents, AClosedAndAnOpenComponentCastEachTheirOwnWay) {
  const SilhouetteComponents c = components_of(tetrahedron() + Triangles{{4, 5, 6}}, 7);
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.silhouette_components, 1u);
  EXPECT_EQ(c.silhouette_face, (std::vector<uint8_t>{1, 1, 1, 1, 0}));
  EXPECT_EQ(c.phrase(), "open, 1 hole; 1 of 2 components closed");
  EXPECT_EQ(c.volume_phrase(), "silhouette volume for its 1 closed component, edge multiplicity for the other 1");
}

TEST(SilhouetteComponents, NoFacesIsSaidSo) {
  const SilhouetteComponents c = components_of({}, 0);
  EXPECT_EQ(c.phrase(), "no faces");
  EXPECT_FALSE(c.all_cast_from_silhouette());
}

}  // namespace
}  // namespace umbra
