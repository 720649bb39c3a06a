#include "mesh/half_edge_mesh.hpp"

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

}  // namespace umbra
