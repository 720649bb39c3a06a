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
#include "silhouette/volume_indices.hpp"

namespace umbra {

// The silhouette edges, each as (a, b) in the direction the facing face runs along it.
std::vector<std::array<uint32_t, 2>> silhouette_edges(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing);

// The volume's parts for a given classify_light_facing output, appended to
// `volume`: the caps, then (after every other part's caps) the side quads.
void append_silhouette_caps(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing, MeshVolumeIndices& volume);
void append_silhouette_quads(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing, MeshVolumeIndices& volume);

// The whole volume, replacing `volume`'s. `facing` is scratch space
// (classify_light_facing' output), kept by the caller so that a frame allocates
// nothing once the buffers have grown.
void mesh_volume_indices(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing,
                         MeshVolumeIndices& volume);

// The same volume with its vertices: for tests, `umbra volume` and the
// fallback's common path.
ShadowVolume mesh_shadow_volume(const MeshAdjacency& mesh, const glm::dvec3& light);

// The reference method for any mesh: every triangle's own volume (Crow 1977,
// "Shadow algorithms for computer graphics"),
// correct for any triangle soup, and slow (`--method triangles`).
ShadowVolume per_triangle_volume(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<uint32_t, 3>>& triangles, const glm::dvec3& light);

}  // namespace umbra
