#include "mesh/half_edge_mesh.hpp"

#include <stdexcept>
#include <string>

namespace umbra {

HalfEdgeMesh build_half_edge_mesh(const std::vector<glm::dvec3>& positions,
                                  const std::vector<std::array<uint32_t, 3>>& triangles) {
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
