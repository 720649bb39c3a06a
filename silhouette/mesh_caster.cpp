#include "silhouette/mesh_caster.hpp"

#include <stdexcept>

#include "silhouette/light_facing.hpp"
#include "silhouette/mesh_volume.hpp"

namespace umbra {

MeshCaster prepare_mesh_caster(const SharedPositions& positions,
                               const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                               const SilhouetteComponents& components) {
  MeshCaster caster;
  caster.positions = positions;
  caster.shape = components.phrase();
  std::vector<uint8_t> open_face(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) open_face[t] = !components.silhouette_face[t];
  caster.volume_phrase = components.volume_phrase();
  if (components.silhouette_components > 0) {
    try {
      caster.silhouette = build_mesh_adjacency(positions, triangles, edges, components.silhouette_face);
    } catch (const std::invalid_argument&) {
      // The edge table proved these components closed 2-manifolds; should
      // linking one fail, multiplicity is exact too.
      open_face.assign(triangles.size(), 1);
      caster.volume_phrase = "edge-multiplicity volume (OpenMesh refused its closed components)";
    }
  }
  caster.open = build_multiplicity_adjacency(positions, triangles, edges, open_face);
  return caster;
}

MeshCaster prepare_mesh_caster(const SharedPositions& positions, const std::vector<std::array<uint32_t, 3>>& triangles) {
  const EdgeTable edges = build_edge_table(triangles, positions.size());
  return prepare_mesh_caster(positions, triangles, edges, find_silhouette_components(triangles, edges, positions.size()));
}

void mesh_caster_volume_indices(const MeshCaster& caster, const glm::dvec3& light, MeshCasterScratch& scratch,
                                MeshVolumeIndices& volume, bool with_caps) {
  const uint32_t far = uint32_t(caster.positions.size());
  volume.clear();
  if (!caster.silhouette.triangles.empty()) classify_light_facing(caster.silhouette, light, scratch.facing);
  classify_light_sides(caster.positions, caster.open, light, scratch.side);
  if (with_caps) {
    if (!caster.silhouette.triangles.empty()) append_silhouette_caps(caster.silhouette, scratch.facing, volume);
    append_multiplicity_caps(caster.open, scratch.side, far, volume);
  }
  if (!caster.silhouette.triangles.empty()) append_silhouette_quads(caster.silhouette, scratch.facing, volume);
  append_multiplicity_quads(caster.open, scratch.side, far, volume);
}

ShadowVolume mesh_caster_volume(const MeshCaster& caster, const glm::dvec3& light) {
  MeshCasterScratch scratch;
  MeshVolumeIndices indices;
  mesh_caster_volume_indices(caster, light, scratch, indices);
  return with_vertices(indices, caster.positions, light);
}

}  // namespace umbra
