#pragma once
// What a silhouette pass reads, as flat arrays built once per mesh from its
// OpenMesh half-edge structure: per light and frame only classify_faces and
// the extraction run, streaming over these arrays.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/half_edge_mesh.hpp"

namespace umbra {

struct MeshAdjacency {
  // Face t's plane: n . x - offset has the sign of orient3d(a, b, c, x) for
  // n = (b - a) x (c - a), up to the rounding bound
  // error_per_light_distance * |x| + error_constant (both rounded up).
  struct FacePlane {
    glm::dvec3 normal;
    double offset;
    float error_per_light_distance;
    float error_constant;
  };
  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<FacePlane> planes;
  // Edge e lies between faces edge_faces[e] = {left, right}: the left face
  // runs along it from edge_vertices[e][0] to edge_vertices[e][1], the right
  // face back. Two arrays, because every frame reads the faces of every edge
  // but the vertices only of the few silhouette edges.
  std::vector<std::array<uint32_t, 2>> edge_faces;
  std::vector<std::array<uint32_t, 2>> edge_vertices;
};

// Requires a closed triangle mesh (every halfedge has a face).
MeshAdjacency build_mesh_adjacency(const HalfEdgeMesh& mesh);

}  // namespace umbra
