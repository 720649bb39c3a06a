#pragma once
// The OpenMesh half-edge structure of a closed, consistently oriented
// 2-manifold triangle mesh: what silhouette extraction walks.

#include <array>
#include <cstdint>
#include <vector>

// OpenMesh's vectors leave their coordinates uninitialised on purpose, which
// GCC 12 reports from inside OpenMesh's property code; the warning is theirs.
#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#pragma GCC diagnostic pop
#include <glm/vec3.hpp>

#include "mesh/topology/edge_table.hpp"

namespace umbra {

struct HalfEdgeTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;  // the file's coordinates, unrounded
  VertexAttributes(OpenMesh::Attributes::None);
  HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
  EdgeAttributes(OpenMesh::Attributes::None);
  FaceAttributes(OpenMesh::Attributes::None);
};
using HalfEdgeMesh = OpenMesh::TriMesh_ArrayKernelT<HalfEdgeTraits>;

// Builds the half-edge mesh of triangles that check_mesh found to be closed
// and consistently oriented (MeshReport::volume_kind() is kSilhouette).
// Vertex i and face t are positions[i] and triangles[t]. Throws
// std::invalid_argument when OpenMesh refuses a triangle, which such input
// never makes it do.
HalfEdgeMesh build_half_edge_mesh(const std::vector<glm::dvec3>& positions,
                                  const std::vector<std::array<uint32_t, 3>>& triangles);

// The same half-edge structure for the triangles t with silhouette_face[t] set,
// which find_silhouette_components proved to be closed, consistently oriented
// 2-manifolds, linked straight from their edge table: no search for each
// half-edge as OpenMesh's add_face does, and no second sort of the edges.
// Face i is the i-th marked triangle, vertex v is positions[v], and edges
// come in the table's order.
HalfEdgeMesh link_half_edge_mesh(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                 const std::vector<uint8_t>& silhouette_face);

}  // namespace umbra
