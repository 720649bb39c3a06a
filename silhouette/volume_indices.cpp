#include "silhouette/volume_indices.hpp"

namespace umbra {

ShadowVolume with_vertices(const MeshVolumeIndices& indices, const std::vector<glm::dvec3>& positions,
                           const glm::dvec3& light) {
  ShadowVolume volume;
  volume.vertices.reserve(2 * positions.size());
  for (const glm::dvec3& p : positions) volume.vertices.emplace_back(p, 1.0);
  for (const glm::dvec3& p : positions) volume.vertices.emplace_back(p - light, 0.0);
  volume.triangles.reserve(indices.count / 3);
  for (size_t i = 0; i + 2 < indices.count; i += 3)
    volume.triangles.push_back({indices.buffer[i], indices.buffer[i + 1], indices.buffer[i + 2]});
  volume.side_quads = indices.side_quads;
  volume.light_cap_triangles = indices.light_cap_triangles;
  volume.dark_cap_triangles = indices.dark_cap_triangles;
  return volume;
}

}  // namespace umbra
