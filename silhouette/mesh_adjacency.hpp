#pragma once
// What a silhouette pass reads, as flat arrays built once per mesh from its
// OpenMesh half-edge structure (which no interface above this one sees): per
// light and frame only classify_light_facing and the extraction run, streaming over
// these arrays.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/shared_positions.hpp"
#include "mesh/topology/edge_table.hpp"
#include "mesh/unset_vector.hpp"
#include "silhouette/face_plane.hpp"

namespace umbra {

struct MeshAdjacency {
  using FacePlane = umbra::FacePlane;
  SharedPositions positions;  // the mesh's, shared: the structure's own copy is not kept
  std::vector<std::array<uint32_t, 3>> triangles;
  UnsetVector<FacePlane> planes;  // sized, then filled on every core
  // Edge e lies between faces edge_faces[e] = {left, right}: the left face
  // runs along it from edge_vertices[e][0] to edge_vertices[e][1], the right
  // face back. Two arrays, because every frame reads the faces of every edge
  // but the vertices only of the few silhouette edges.
  UnsetVector<std::array<uint32_t, 2>> edge_faces;
  UnsetVector<std::array<uint32_t, 2>> edge_vertices;
};

// The arrays of a closed, consistently oriented 2-manifold triangle mesh:
// each edge's faces and vertices walked from its OpenMesh half-edge
// structure (build_half_edge_mesh), which stays inside this function; the
// faces are the triangles, in order, that the structure was made from.
// Throws std::invalid_argument when OpenMesh refuses a triangle or a
// halfedge has no face.
MeshAdjacency build_mesh_adjacency(const SharedPositions& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles);

// The same for the triangles marked in silhouette_face, which
// find_silhouette_components proved closed (link_half_edge_mesh): what the
// renderer uses, in linear time from the edge table it already has.
MeshAdjacency build_mesh_adjacency(const SharedPositions& positions,
                                   const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                   const std::vector<uint8_t>& silhouette_face);

}  // namespace umbra
