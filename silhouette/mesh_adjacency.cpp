#include "silhouette/mesh_adjacency.hpp"

#include "mesh/topology/half_edge_mesh.hpp"

#include <atomic>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

namespace umbra {

namespace {

// The flat arrays, walked from the half-edge structure: each vertex, face
// and edge on its own, so on every core.
MeshAdjacency flatten(const HalfEdgeMesh& mesh) {
  const auto each = [](size_t count, const auto& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i < range.end(); ++i) body(int(i));
    });
  };
  MeshAdjacency adjacency;
  adjacency.positions.resize(mesh.n_vertices());
  each(mesh.n_vertices(), [&](int v) {
    const auto& p = mesh.point(OpenMesh::VertexHandle(v));
    adjacency.positions[size_t(v)] = glm::dvec3(p[0], p[1], p[2]);
  });
  adjacency.triangles.resize(mesh.n_faces());
  adjacency.planes.resize(mesh.n_faces());
  each(mesh.n_faces(), [&](int f) {
    // The vertices each half-edge of the face runs to, in turn (as OpenMesh's
    // face-vertex circulator lists them).
    const OpenMesh::HalfedgeHandle h0 = mesh.halfedge_handle(OpenMesh::FaceHandle(f));
    const OpenMesh::HalfedgeHandle h1 = mesh.next_halfedge_handle(h0);
    const std::array<uint32_t, 3> tri{uint32_t(mesh.to_vertex_handle(h0).idx()), uint32_t(mesh.to_vertex_handle(h1).idx()),
                                      uint32_t(mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)).idx())};
    adjacency.triangles[size_t(f)] = tri;
    adjacency.planes[size_t(f)] =
        face_plane(adjacency.positions[tri[0]], adjacency.positions[tri[1]], adjacency.positions[tri[2]]);
  });
  adjacency.edge_faces.resize(mesh.n_edges());
  adjacency.edge_vertices.resize(mesh.n_edges());
  std::atomic<bool> border{false};
  each(mesh.n_edges(), [&](int e) {
    const auto h = mesh.halfedge_handle(OpenMesh::EdgeHandle(e), 0);
    const auto opposite = mesh.opposite_halfedge_handle(h);
    if (mesh.is_boundary(h) || mesh.is_boundary(opposite)) border = true;
    adjacency.edge_faces[size_t(e)] = {uint32_t(mesh.face_handle(h).idx()), uint32_t(mesh.face_handle(opposite).idx())};
    adjacency.edge_vertices[size_t(e)] = {uint32_t(mesh.from_vertex_handle(h).idx()), uint32_t(mesh.to_vertex_handle(h).idx())};
  });
  if (border) throw std::invalid_argument("build_mesh_adjacency needs a closed mesh");
  return adjacency;
}

}  // namespace

MeshAdjacency build_mesh_adjacency(const std::vector<glm::dvec3>& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles) {
  return flatten(build_half_edge_mesh(positions, triangles));
}

MeshAdjacency build_mesh_adjacency(const std::vector<glm::dvec3>& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                   const std::vector<uint8_t>& closed_face) {
  return flatten(link_half_edge_mesh(positions, triangles, edges, closed_face));
}

}  // namespace umbra
