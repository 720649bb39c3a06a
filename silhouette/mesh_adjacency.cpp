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

// The flat arrays: the edges' faces and vertices walked from the half-edge
// structure; the faces are `faces` and the points `positions`, which it was
// made from (face f runs round faces[f], as OpenMesh keeps the order faces
// are added in; vertex v is positions[v]), their planes computed in that
// order rather than by three jumps per face across the half-edge array. Each
// face and edge on its own, on every core.
MeshAdjacency flatten(const HalfEdgeMesh& mesh, const SharedPositions& positions, std::vector<std::array<uint32_t, 3>> faces) {
  if (faces.size() != mesh.n_faces() || positions.size() != mesh.n_vertices())
    throw std::logic_error("flatten: the faces or points are not the mesh's");
  const auto each = [](size_t count, const auto& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i < range.end(); ++i) body(int(i));
    });
  };
  MeshAdjacency adjacency;
  adjacency.positions = positions;
  adjacency.triangles = std::move(faces);
  adjacency.planes.resize(adjacency.triangles.size());
  each(adjacency.triangles.size(), [&](int f) {
    if (size_t(f) + kAhead < adjacency.triangles.size())  // the corners lie anywhere: fetched a few faces ahead
      for (const uint32_t v : adjacency.triangles[size_t(f) + kAhead]) __builtin_prefetch(&adjacency.positions[v]);
    const auto& tri = adjacency.triangles[size_t(f)];
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

MeshAdjacency build_mesh_adjacency(const SharedPositions& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles) {
  return flatten(build_half_edge_mesh(positions, triangles), positions, triangles);
}

MeshAdjacency build_mesh_adjacency(const SharedPositions& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                   const std::vector<uint8_t>& closed_face) {
  std::vector<std::array<uint32_t, 3>> closed;  // the linked mesh's faces, in order
  closed.reserve(size_t(std::count(closed_face.begin(), closed_face.end(), 1)));
  for (size_t t = 0; t < triangles.size(); ++t)
    if (closed_face[t]) closed.push_back(triangles[t]);
  return flatten(link_half_edge_mesh(positions, triangles, edges, closed_face), positions, std::move(closed));
}

}  // namespace umbra
