// The half-edge mesh built from the check's triangles: OpenMesh agrees that
// what the check calls closed and consistently oriented is.
#include <gtest/gtest.h>

#include "mesh/half_edge_mesh.hpp"
#include "mesh/mesh_check.hpp"
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

TEST(HalfEdgeMesh, NonManifoldEdgeIsRefusedWithAReason) {
  const MeshAnalysis a = analyse_mesh(combine(unit_cube(), box_triangles({1, 1, 0}, {2, 2, 1})));
  ASSERT_EQ(a.report.non_manifold_edges, 1u);
  EXPECT_THROW(build_half_edge_mesh(a.positions, a.triangles), std::invalid_argument);
}

}  // namespace
}  // namespace umbra
