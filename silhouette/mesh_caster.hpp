#pragma once
// What each mesh of a scene needs to cast shadows, prepared once per scene:
// its closed 2-manifold components cast from their silhouette (over an
// OpenMesh half-edge structure), every other face by edge multiplicity. Both
// are exact; the silhouette volume has about half the triangles. Per light
// and frame, only the index list of one volume over the mesh's static
// vertices is made.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/shared_positions.hpp"
#include "mesh/topology/silhouette_components.hpp"
#include "mesh/topology/edge_table.hpp"
#include "silhouette/mesh_adjacency.hpp"
#include "silhouette/multiplicity_volume.hpp"
#include "silhouette/shadow_volume.hpp"
#include "silhouette/volume_indices.hpp"

namespace umbra {

struct MeshCaster {
  SharedPositions positions;   // the mesh's own array, shared, not copied
  MeshAdjacency silhouette;        // the faces of closed, consistently oriented 2-manifold components
  MultiplicityAdjacency open;  // every other face
  std::string shape;           // SilhouetteComponents::phrase(): "closed 2-manifold", "open, 3 holes", ...
  std::string volume_phrase;   // "silhouette volume", "edge-multiplicity volume", or which parts get which

  // "open, 3 holes: edge-multiplicity volume"
  std::string phrase() const { return shape + ": " + volume_phrase; }
};

// `edges` and `components` are those of `triangles`. The caster and its
// silhouette arrays share `positions` rather than copy them.
MeshCaster prepare_mesh_caster(const SharedPositions& positions,
                               const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                               const SilhouetteComponents& components);
// The same, finding the edges and components itself.
MeshCaster prepare_mesh_caster(const SharedPositions& positions, const std::vector<std::array<uint32_t, 3>>& triangles);

// What a frame's classification writes, kept by the caller so that a frame
// allocates nothing once it has grown.
struct MeshCasterScratch {
  std::vector<uint8_t> facing;  // the closed part's faces
  std::vector<int8_t> side;     // the open part's faces
};

// The mesh's volume for `light`, replacing `volume`'s: both parts' caps, then
// both parts' side quads; without caps for a light counted with z-pass,
// which draws none.
void mesh_caster_volume_indices(const MeshCaster& caster, const glm::dvec3& light, MeshCasterScratch& scratch,
                                MeshVolumeIndices& volume, bool with_caps = true);
// The same with its vertices: for tests and `umbra volume`.
ShadowVolume mesh_caster_volume(const MeshCaster& caster, const glm::dvec3& light);

}  // namespace umbra
