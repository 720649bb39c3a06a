#include "mesh/topology/half_edge_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

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
                                 const std::vector<uint8_t>& closed_face) {
  constexpr uint32_t kNone = ~uint32_t(0);
  std::vector<uint32_t> face_of_triangle(triangles.size(), kNone);
  uint32_t face_count = 0;
  for (size_t t = 0; t < triangles.size(); ++t)
    if (closed_face[t]) face_of_triangle[t] = face_count++;

  HalfEdgeMesh mesh;
  mesh.reserve(positions.size(), size_t(face_count) * 3 / 2, face_count);
  for (const glm::dvec3& p : positions) mesh.add_vertex(HalfEdgeMesh::Point(p.x, p.y, p.z));
  // Each edge's two half-edges, filed under the corner of the face they leave.
  std::vector<OpenMesh::HalfedgeHandle> corner_halfedge(size_t(face_count) * 3);
  for (size_t e = 0; e < edges.size(); ++e) {
    const uint32_t first = edges.first_use[e];
    if (edges.use_count(e) != 2 || !closed_face[EdgeTable::face_of(edges.uses[first])]) continue;
    const auto [a, b] = edges.vertices[e];
    const OpenMesh::HalfedgeHandle forward = mesh.new_edge(OpenMesh::VertexHandle(int(a)), OpenMesh::VertexHandle(int(b)));
    for (uint32_t k = first; k < first + 2; ++k) {
      const uint32_t t = EdgeTable::face_of(edges.uses[k]);
      const bool runs_forward = EdgeTable::runs_forward(edges.uses[k]);
      const uint32_t from = runs_forward ? a : b;
      const size_t corner = triangles[t][0] == from ? 0 : triangles[t][1] == from ? 1 : 2;
      corner_halfedge[size_t(face_of_triangle[t]) * 3 + corner] = runs_forward ? forward : mesh.opposite_halfedge_handle(forward);
    }
  }
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (face_of_triangle[t] == kNone) continue;
    const OpenMesh::FaceHandle face = mesh.new_face();
    const OpenMesh::HalfedgeHandle* h = &corner_halfedge[size_t(face_of_triangle[t]) * 3];
    for (size_t k = 0; k < 3; ++k) {
      if (!h[k].is_valid()) throw std::invalid_argument("link_half_edge_mesh: triangle " + std::to_string(t) + " is not closed");
      mesh.set_next_halfedge_handle(h[k], h[(k + 1) % 3]);
      mesh.set_face_handle(h[k], face);
      mesh.set_halfedge_handle(OpenMesh::VertexHandle(int(triangles[t][k])), h[k]);  // any outgoing one: there is no border
    }
    mesh.set_halfedge_handle(face, h[0]);
  }
  return mesh;
}

}  // namespace umbra
