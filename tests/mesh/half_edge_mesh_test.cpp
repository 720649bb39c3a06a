// The half-edge mesh built from the check's triangles: OpenMesh agrees that
// what the check calls closed and consistently oriented is.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "mesh/topology/silhouette_components.hpp"
#include "mesh/topology/half_edge_mesh.hpp"
#include "mesh/check/mesh_check.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

using namespace umbra::test;

size_t boundary_halfedges(const HalfEdgeMesh& mesh) {
  size_t n = 0;
  for (const auto h : mesh.halfedges()) n += mesh.is_boundary(h);
  return n;
}

TEST(HalfEdgeMesh, CubeOfQuadsBecomesAClosedTriangleMesh) {
  const MeshAnalysis a = analyse_mesh(box_quads(glm::dvec3(0.0), glm::dvec3(1.0)));
  const HalfEdgeMesh mesh = build_half_edge_mesh(a.positions, a.triangles);
  EXPECT_EQ(mesh.n_vertices(), 8u);
  EXPECT_EQ(mesh.n_edges(), 18u);
  EXPECT_EQ(mesh.n_faces(), 12u);
  EXPECT_EQ(boundary_halfedges(mesh), 0u);
}

TEST(HalfEdgeMesh, FacesTheCheckFlipsAreFlippedInTheTriangles) {
  // Face 7 reversed: OpenMesh would refuse it as written; the analysis turns it back.
  const MeshAnalysis a = analyse_mesh(reversed(unit_cube(), {7}));
  EXPECT_EQ(a.report.faces_to_flip, 1u);
  const HalfEdgeMesh mesh = build_half_edge_mesh(a.positions, a.triangles);
  EXPECT_EQ(boundary_halfedges(mesh), 0u);
  EXPECT_EQ(mesh.n_faces(), 12u);
}

TEST(HalfEdgeMesh, TorusKeepsItsGenus) {
  const MeshAnalysis a = analyse_mesh(quad_torus(8, 6));
  const HalfEdgeMesh mesh = build_half_edge_mesh(a.positions, a.triangles);
  EXPECT_EQ(int64_t(mesh.n_vertices()) - int64_t(mesh.n_edges()) + int64_t(mesh.n_faces()), 0);
}

// Every half-edge of `mesh` as (from, to) -> (face's vertices from there on,
// next half-edge's head, previous half-edge's tail, opposite's face vertices):
// the whole connectivity, independent of the order elements were made in.
std::map<std::pair<int, int>, std::array<int, 6>> connectivity(const HalfEdgeMesh& mesh) {
  std::map<std::pair<int, int>, std::array<int, 6>> out;
  const auto face_key = [&mesh](OpenMesh::FaceHandle f) {
    int smallest = INT32_MAX;
    for (const auto v : mesh.fv_range(f)) smallest = std::min(smallest, v.idx());
    return smallest;
  };
  for (const auto h : mesh.halfedges()) {
    const auto f = mesh.face_handle(h);
    const auto o = mesh.opposite_halfedge_handle(h);
    out[{mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx()}] = {
        f.is_valid() ? face_key(f) : -1,
        mesh.to_vertex_handle(mesh.next_halfedge_handle(h)).idx(),
        mesh.from_vertex_handle(mesh.prev_halfedge_handle(h)).idx(),
        mesh.face_handle(o).is_valid() ? face_key(mesh.face_handle(o)) : -1,
        int(mesh.valence(mesh.from_vertex_handle(h))),
        int(mesh.is_boundary(h))};
  }
  return out;
}

TEST(HalfEdgeMesh, LinkedFromTheEdgeTableItIsTheMeshOpenMeshBuildsFaceByFace) {
  for (const PolygonSoup& soup : {unit_cube(), quad_torus(8, 6), uv_sphere(9, 13), hollow_cube(), octahedron()}) {
    const MeshAnalysis a = analyse_mesh(soup);
    const EdgeTable edges = build_edge_table(a.triangles, a.positions.size());
    const SilhouetteComponents closed = find_silhouette_components(a.triangles, edges, a.positions.size());
    ASSERT_TRUE(closed.all_cast_from_silhouette());
    const HalfEdgeMesh linked = link_half_edge_mesh(a.positions, a.triangles, edges, closed.silhouette_face);
    const HalfEdgeMesh built = build_half_edge_mesh(a.positions, a.triangles);
    EXPECT_EQ(linked.n_faces(), built.n_faces());
    EXPECT_EQ(linked.n_edges(), built.n_edges());
    EXPECT_EQ(boundary_halfedges(linked), 0u);
    EXPECT_EQ(connectivity(linked), connectivity(built));
    for (const auto f : linked.faces()) {  // face i is triangle i, vertices in its order
      std::vector<int> corners;
      for (const auto v : linked.fv_range(f)) corners.push_back(v.idx());
      const auto& t = a.triangles[size_t(f.idx())];
      std::rotate(corners.begin(), std::find(corners.begin(), corners.end(), int(t[0])), corners.end());
      EXPECT_EQ(corners, (std::vector<int>{int(t[0]), int(t[1]), int(t[2])}));
    }
  }
}

TEST(HalfEdgeMesh, LinkedMeshHoldsOnlyTheClosedFacesOfAMixedMesh) {
  // A closed cube and an open one: only the closed cube's 12 triangles are linked.
  const MeshAnalysis a = analyse_mesh(combine(unit_cube(), without_faces(box_triangles(glm::dvec3(3.0), glm::dvec3(4.0)), {0})));
  const EdgeTable edges = build_edge_table(a.triangles, a.positions.size());
  const SilhouetteComponents closed = find_silhouette_components(a.triangles, edges, a.positions.size());
  ASSERT_EQ(closed.silhouette_components, 1u);
  const HalfEdgeMesh linked = link_half_edge_mesh(a.positions, a.triangles, edges, closed.silhouette_face);
  EXPECT_EQ(linked.n_faces(), 12u);
  EXPECT_EQ(linked.n_edges(), 18u);
  EXPECT_EQ(boundary_halfedges(linked), 0u);
}

TEST(HalfEdgeMesh, NonManifoldEdgeIsRefusedWithAReason) {
  const MeshAnalysis a = analyse_mesh(combine(unit_cube(), box_triangles({1, 1, 0}, {2, 2, 1})));
  ASSERT_EQ(a.report.non_manifold_edges, 1u);
  EXPECT_THROW(build_half_edge_mesh(a.positions, a.triangles), std::invalid_argument);
}

}  // namespace
}  // namespace umbra
