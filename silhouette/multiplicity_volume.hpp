#pragma once
// The shadow volume of any triangle mesh (borders, non-manifold edges, mixed
// winding, several or interpenetrating components, self-intersections) by
// edge multiplicity, at about the cost of a closed mesh's silhouette volume.
//
// Each face is oriented toward the light (the exact side test); a face whose
// plane holds the light casts nothing. Each edge's multiplicity m sums, over
// its faces, +1 for a face that runs along it from its first vertex to its
// second once oriented, -1 for one that runs back. The edge's side quad is
// drawn |m| times, wound as the sign says, and not at all where m = 0; every
// oriented face is a light cap, and its image at infinity a dark cap. That is
// the sum of the faces' own volumes (Crow 1977) with every quad that two faces
// share in opposite directions cancelled, so the stencil count at a point is
// the number of faces between it and the light, as per-triangle volumes count
// it (Aldridge and Woods 2004, "Robust, geometry-independent shadow volumes";
// Kim, Kim and Turk 2008, "A shadow volume algorithm for opaque and
// transparent non-manifold casters").
//
// Every use of a face (its caps and its share of each edge's m) reads the one
// side computed for that face, so rounding can never make two edges of a face,
// or two faces of an edge, disagree: the volume is a closed surface always.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/topology/edge_table.hpp"
#include "silhouette/face_plane.hpp"
#include "silhouette/shadow_volume.hpp"
#include "silhouette/volume_indices.hpp"

namespace umbra {

// Flat arrays for a subset of a mesh's faces, built once per mesh. Faces are
// numbered within the subset; vertices are the mesh's.
struct MultiplicityAdjacency {
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<FacePlane> planes;
  // Edges with exactly two uses (almost all of them): each use is
  // face << 1 | 1 when the face, as stored, runs from vertices[0] to
  // vertices[1].
  std::vector<std::array<uint32_t, 2>> pair_uses;
  std::vector<std::array<uint32_t, 2>> pair_vertices;
  // Every other edge (a border's one use, a non-manifold edge's three or
  // more): uses other_uses[other_first_use[k] .. other_first_use[k + 1]).
  std::vector<uint32_t> other_first_use{0};
  std::vector<uint32_t> other_uses;
  std::vector<std::array<uint32_t, 2>> other_vertices;

  bool empty() const { return triangles.empty(); }
};

// The faces t with in_subset[t] = 1 of a mesh whose edge table is `edges`:
// any subset, whose volume counts only its own faces (an edge counts the
// uses of the subset's faces alone).
MultiplicityAdjacency build_multiplicity_adjacency(const std::vector<glm::dvec3>& positions,
                                                   const std::vector<std::array<uint32_t, 3>>& triangles,
                                                   const EdgeTable& edges, const std::vector<uint8_t>& in_subset);

// side[t] = +1 when face t (as stored) faces the light, -1 when it faces
// away, 0 when its plane holds the light or it is degenerate: exact.
void classify_light_sides(const std::vector<glm::dvec3>& positions, const MultiplicityAdjacency& mesh,
                          const glm::dvec3& light, std::vector<int8_t>& side);

// The volume's caps, then (after every other part's caps) its side quads,
// appended to `volume`; `far` is the mesh's vertex count.
void append_multiplicity_caps(const MultiplicityAdjacency& mesh, const std::vector<int8_t>& side, uint32_t far,
                              MeshVolumeIndices& volume);
void append_multiplicity_quads(const MultiplicityAdjacency& mesh, const std::vector<int8_t>& side, uint32_t far,
                               MeshVolumeIndices& volume);

// The whole volume with its vertices: for tests and `umbra volume`.
ShadowVolume multiplicity_shadow_volume(const std::vector<glm::dvec3>& positions, const MultiplicityAdjacency& mesh,
                                        const glm::dvec3& light);

}  // namespace umbra
