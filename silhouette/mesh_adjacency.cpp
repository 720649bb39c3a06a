#include "silhouette/mesh_adjacency.hpp"

#include "mesh/topology/half_edge_mesh.hpp"

#include <stdexcept>

#include <glm/geometric.hpp>

namespace umbra {

namespace {

// The flat arrays, walked from the half-edge structure.
MeshAdjacency flatten(const HalfEdgeMesh& mesh) {
  MeshAdjacency adjacency;
  adjacency.positions.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    adjacency.positions.emplace_back(p[0], p[1], p[2]);
  }
  adjacency.triangles.reserve(mesh.n_faces());
  adjacency.planes.reserve(mesh.n_faces());
  for (const auto f : mesh.faces()) {
    std::array<uint32_t, 3> tri{};
    int k = 0;
    for (const auto v : mesh.fv_range(f)) tri[size_t(k++)] = uint32_t(v.idx());
    adjacency.triangles.push_back(tri);
    adjacency.planes.push_back(
        face_plane(adjacency.positions[tri[0]], adjacency.positions[tri[1]], adjacency.positions[tri[2]]));
  }
  adjacency.edge_faces.reserve(mesh.n_edges());
  adjacency.edge_vertices.reserve(mesh.n_edges());
  for (const auto e : mesh.edges()) {
    const auto h = mesh.halfedge_handle(e, 0);
    const auto opposite = mesh.opposite_halfedge_handle(h);
    if (mesh.is_boundary(h) || mesh.is_boundary(opposite))
      throw std::invalid_argument("build_mesh_adjacency needs a closed mesh");
    adjacency.edge_faces.push_back({uint32_t(mesh.face_handle(h).idx()), uint32_t(mesh.face_handle(opposite).idx())});
    adjacency.edge_vertices.push_back({uint32_t(mesh.from_vertex_handle(h).idx()), uint32_t(mesh.to_vertex_handle(h).idx())});
  }
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
