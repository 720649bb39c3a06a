#include "silhouette/mesh_adjacency.hpp"

#include "mesh/topology/half_edge_mesh.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

namespace umbra {

namespace {

constexpr size_t kAhead = 8;  // faces

// The edges' faces and vertices, walked from the half-edge structure on
// every core. `faces` and `points` are how many the structure was made from.
MeshAdjacency edges_of(const HalfEdgeMesh& mesh, size_t faces, size_t points) {
  if (faces != mesh.n_faces() || points != mesh.n_vertices())
    throw std::logic_error("build_mesh_adjacency: the faces or points are not the mesh's");
  MeshAdjacency adjacency;
  adjacency.edge_faces.resize(mesh.n_edges());
  adjacency.edge_vertices.resize(mesh.n_edges());
  std::atomic<bool> border{false};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.n_edges()), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t e = range.begin(); e < range.end(); ++e) {
      const auto h = mesh.halfedge_handle(OpenMesh::EdgeHandle(int(e)), 0);
      const auto opposite = mesh.opposite_halfedge_handle(h);
      if (mesh.is_boundary(h) || mesh.is_boundary(opposite)) border = true;
      adjacency.edge_faces[e] = {uint32_t(mesh.face_handle(h).idx()), uint32_t(mesh.face_handle(opposite).idx())};
      adjacency.edge_vertices[e] = {uint32_t(mesh.from_vertex_handle(h).idx()), uint32_t(mesh.to_vertex_handle(h).idx())};
    }
  });
  if (border) throw std::invalid_argument("build_mesh_adjacency needs a closed mesh");
  return adjacency;
}

// The faces and their planes, made once the half-edge structure is gone
// (made beside it, they raise a large mesh's peak: docs/performance.md, "A
// closed mesh's half-edge structure, freed first"): the faces are the
// structure's, in order (OpenMesh keeps the order faces are added in;
// vertex v is positions[v]), their planes computed in that order rather
// than by three jumps per face across the half-edge array, on every core.
void add_faces(MeshAdjacency& adjacency, const SharedPositions& positions, std::vector<std::array<uint32_t, 3>> faces) {
  adjacency.positions = positions;
  adjacency.triangles = std::move(faces);
  adjacency.planes.resize(adjacency.triangles.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, adjacency.triangles.size()), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t f = range.begin(); f < range.end(); ++f) {
      if (f + kAhead < adjacency.triangles.size())  // the corners lie anywhere: fetched a few faces ahead
        for (const uint32_t v : adjacency.triangles[f + kAhead]) __builtin_prefetch(&adjacency.positions[v]);
      const auto& tri = adjacency.triangles[f];
      adjacency.planes[f] = face_plane(adjacency.positions[tri[0]], adjacency.positions[tri[1]], adjacency.positions[tri[2]]);
    }
  });
}

}  // namespace

// Each builds the half-edge structure as a temporary, which is freed once
// its edges are walked, before the faces' arrays are made.
MeshAdjacency build_mesh_adjacency(const SharedPositions& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles) {
  MeshAdjacency adjacency = edges_of(build_half_edge_mesh(positions, triangles), triangles.size(), positions.size());
  add_faces(adjacency, positions, triangles);
  return adjacency;
}

MeshAdjacency build_mesh_adjacency(const SharedPositions& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                   const std::vector<uint8_t>& silhouette_face) {
  const size_t closed_count = size_t(std::count(silhouette_face.begin(), silhouette_face.end(), 1));
  MeshAdjacency adjacency =
      edges_of(link_half_edge_mesh(positions, triangles, edges, silhouette_face), closed_count, positions.size());
  std::vector<std::array<uint32_t, 3>> closed;  // the linked mesh's faces, in order
  closed.reserve(closed_count);
  for (size_t t = 0; t < triangles.size(); ++t)
    if (silhouette_face[t]) closed.push_back(triangles[t]);
  add_faces(adjacency, positions, std::move(closed));
  return adjacency;
}

}  // namespace umbra
