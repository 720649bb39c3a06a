#pragma once
// The shadow volume of a closed, consistently oriented triangle mesh from its
// silhouette: side quads extruded to infinity from the silhouette edges,
// oriented by the face that faces the light; near cap = the faces that do not
// face the light, reversed; dark cap = the same faces at infinity. This is the
// shadow behind the mesh's lit side less the mesh's own inside, which no
// visible point is in: the same shadow for everything the eye can see, and
// the lit faces are never on the volume's boundary, so they cannot shadow
// themselves by rounding.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "silhouette/mesh_adjacency.hpp"
#include "silhouette/shadow_volume.hpp"

namespace umbra {

// The volume as indices into the mesh's 2N vertices: v < N is mesh vertex v,
// v >= N is mesh vertex v - N at infinity, (P - L, 0). The vertices never
// change with the light, so a renderer keeps them in a static buffer and
// sends only these indices each frame.
struct MeshVolumeIndices {
  // Triangles, counter-clockwise seen from outside the volume: the first
  // `count` entries. The buffer keeps the largest size a volume of the mesh
  // can have, so a frame neither allocates nor clears memory.
  std::vector<uint32_t> buffer;
  size_t count = 0;
  int side_quads = 0;
  int light_cap_triangles = 0;  // the near cap
  int dark_cap_triangles = 0;
};

// The silhouette edges, each as (a, b) in the direction the facing face runs along it.
std::vector<std::array<uint32_t, 2>> silhouette_edges(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing);

// `facing` is scratch space (classify_faces' output), kept by the caller so
// that a frame allocates nothing once the buffers have grown.
void mesh_volume_indices(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing,
                         MeshVolumeIndices& volume);

// The same volume with its vertices: for tests, `umbra volume` and the
// fallback's common path.
ShadowVolume mesh_shadow_volume(const MeshAdjacency& mesh, const glm::dvec3& light);

// The slower method for a mesh that is not a closed, consistently oriented
// 2-manifold: every triangle's own volume (spec 2.1), which is correct for
// any triangle soup.
ShadowVolume per_triangle_volume(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<uint32_t, 3>>& triangles, const glm::dvec3& light);

}  // namespace umbra
