#include "mesh/topology/half_edge_mesh.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace umbra {

HalfEdgeMesh build_half_edge_mesh(const std::vector<glm::dvec3>& positions,
                                  const std::vector<std::array<uint32_t, 3>>& triangles) {
  // A directed edge used twice is a "complex edge" that OpenMesh refuses and
  // reports on stderr itself; find it first, quietly.
  std::vector<uint64_t> directed;
  directed.reserve(triangles.size() * 3);
  for (const auto& tri : triangles)
    for (int i = 0; i < 3; ++i) directed.push_back(uint64_t(tri[size_t(i)]) << 32 | tri[size_t((i + 1) % 3)]);
  std::sort(directed.begin(), directed.end());
  if (std::adjacent_find(directed.begin(), directed.end()) != directed.end())
    throw std::invalid_argument("two triangles run along the same edge in the same direction");

  HalfEdgeMesh mesh;
  mesh.reserve(positions.size(), triangles.size() * 3 / 2, triangles.size());
  for (const glm::dvec3& p : positions) mesh.add_vertex(HalfEdgeMesh::Point(p.x, p.y, p.z));
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const OpenMesh::FaceHandle face = mesh.add_face(OpenMesh::VertexHandle(int(tri[0])), OpenMesh::VertexHandle(int(tri[1])),
                                                    OpenMesh::VertexHandle(int(tri[2])));
    if (!face.is_valid())
      throw std::invalid_argument("OpenMesh refused triangle " + std::to_string(t) +
                                  ": the mesh is not a consistently oriented 2-manifold there");
  }
  return mesh;
}

HalfEdgeMesh link_half_edge_mesh(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                 const std::vector<uint8_t>& silhouette_face) {
  // Every face, edge and vertex is numbered first, so that OpenMesh's arrays
  // are sized once (its new_edge and new_face resize every property array per
  // call) and each element is then written by the one thread that owns it.
  constexpr uint32_t kNone = ~uint32_t(0);
  constexpr size_t kAhead = 8;  // elements fetched ahead
  std::vector<uint32_t> face_of_triangle(triangles.size(), kNone);
  uint32_t face_count = 0;
  for (size_t t = 0; t < triangles.size(); ++t)
    if (silhouette_face[t]) face_of_triangle[t] = face_count++;
  const auto linked = [&](size_t e) {
    return edges.use_count(e) == 2 && silhouette_face[EdgeTable::face_of(edges.uses[edges.first_use[e]])];
  };
  std::vector<uint32_t> edge_of_table_edge(edges.size(), kNone);
  uint32_t edge_count = 0;
  for (size_t e = 0; e < edges.size(); ++e)
    if (linked(e)) edge_of_table_edge[e] = edge_count++;

  HalfEdgeMesh mesh;
  mesh.resize(positions.size(), edge_count, face_count);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, positions.size()), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t v = range.begin(); v < range.end(); ++v)
      mesh.set_point(OpenMesh::VertexHandle(int(v)), HalfEdgeMesh::Point(positions[v].x, positions[v].y, positions[v].z));
  });
  // Edge k's half-edges are 2k (from its first vertex to its second) and
  // 2k + 1, each filed under the corner of the face it leaves.
  std::vector<OpenMesh::HalfedgeHandle> corner_halfedge(size_t(face_count) * 3);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, edges.size()), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t e = range.begin(); e < range.end(); ++e) {
      // An edge's two faces lie anywhere in the triangles: fetched a few
      // edges ahead, and where their corners go once those are in.
      if (e + 2 * kAhead < range.end())
        for (uint32_t k = edges.first_use[e + 2 * kAhead]; k < edges.first_use[e + 2 * kAhead + 1]; ++k) {
          const uint32_t t = EdgeTable::face_of(edges.uses[k]);
          __builtin_prefetch(&triangles[t]);
          __builtin_prefetch(&face_of_triangle[t]);
        }
      if (e + kAhead < range.end())
        for (uint32_t k = edges.first_use[e + kAhead]; k < edges.first_use[e + kAhead + 1]; ++k)
          if (const uint32_t face = face_of_triangle[EdgeTable::face_of(edges.uses[k])]; face != kNone)
            __builtin_prefetch(&corner_halfedge[size_t(face) * 3], 1);
      if (edge_of_table_edge[e] == kNone) continue;
      const auto [a, b] = edges.vertices[e];
      const OpenMesh::HalfedgeHandle forward(int(2 * edge_of_table_edge[e])), backward(int(2 * edge_of_table_edge[e] + 1));
      mesh.set_vertex_handle(forward, OpenMesh::VertexHandle(int(b)));
      mesh.set_vertex_handle(backward, OpenMesh::VertexHandle(int(a)));
      for (uint32_t k = edges.first_use[e]; k < edges.first_use[e] + 2; ++k) {
        const uint32_t t = EdgeTable::face_of(edges.uses[k]);
        const bool runs_forward = EdgeTable::runs_forward(edges.uses[k]);
        const uint32_t from = runs_forward ? a : b;
        const size_t corner = triangles[t][0] == from ? 0 : triangles[t][1] == from ? 1 : 2;
        corner_halfedge[size_t(face_of_triangle[t]) * 3 + corner] = runs_forward ? forward : backward;
      }
    }
  });
  std::atomic<size_t> unlinked{triangles.size()};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles.size()), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t t = range.begin(); t < range.end(); ++t) {
      if (t + kAhead < range.end() && face_of_triangle[t + kAhead] != kNone)  // its half-edges lie anywhere
        for (size_t k = 0; k < 3; ++k)
          if (const OpenMesh::HalfedgeHandle ahead = corner_halfedge[size_t(face_of_triangle[t + kAhead]) * 3 + k]; ahead.is_valid())
            __builtin_prefetch(&mesh.halfedge(ahead), 1);
      if (face_of_triangle[t] == kNone) continue;
      const OpenMesh::FaceHandle face{int(face_of_triangle[t])};
      const OpenMesh::HalfedgeHandle* h = &corner_halfedge[size_t(face.idx()) * 3];
      if (!h[0].is_valid() || !h[1].is_valid() || !h[2].is_valid()) {
        for (size_t seen = unlinked.load(); t < seen && !unlinked.compare_exchange_weak(seen, t);) {}
        continue;
      }
      for (size_t k = 0; k < 3; ++k) {
        mesh.set_next_halfedge_handle(h[k], h[(k + 1) % 3]);
        mesh.set_face_handle(h[k], face);
      }
      mesh.set_halfedge_handle(face, h[0]);
    }
  });
  if (unlinked < triangles.size())
    throw std::invalid_argument("link_half_edge_mesh: triangle " + std::to_string(unlinked.load()) + " is not closed");
  // Any outgoing half-edge will do, there being no border; one thread, as
  // a vertex has several.
  for (size_t t = 0; t < triangles.size(); ++t)
    if (face_of_triangle[t] != kNone)
      for (size_t k = 0; k < 3; ++k)
        mesh.set_halfedge_handle(OpenMesh::VertexHandle(int(triangles[t][k])), corner_halfedge[size_t(face_of_triangle[t]) * 3 + k]);
  return mesh;
}

}  // namespace umbra
