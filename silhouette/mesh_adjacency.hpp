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
  // An edge between two faces; `left_face` runs along it from `from` to `to`,
  // `right_face` from `to` to `from`.
  struct Edge {
    uint32_t from, to, left_face, right_face;
  };

  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<FacePlane> planes;
  std::vector<Edge> edges;
};

// Requires a closed triangle mesh (every halfedge has a face).
MeshAdjacency build_mesh_adjacency(const HalfEdgeMesh& mesh);

}  // namespace umbra
