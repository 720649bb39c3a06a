#include "silhouette/mesh_caster.hpp"

#include <stdexcept>

#include "mesh/half_edge_mesh.hpp"

namespace umbra {

MeshCaster prepare_mesh_caster(ShadowMethod checked, const std::vector<glm::dvec3>& positions,
                               const std::vector<std::array<uint32_t, 3>>& triangles) {
  MeshCaster caster;
  caster.method = checked;
  if (checked != ShadowMethod::kSilhouette) return caster;
  try {
    caster.adjacency = build_mesh_adjacency(build_half_edge_mesh(positions, triangles));
  } catch (const std::invalid_argument&) {
    caster.method = ShadowMethod::kPerTriangle;
    caster.reason = "its polygons make a closed 2-manifold, but their triangles share an edge more than twice "
                    "(a non-planar polygon's diagonal)";
  }
  return caster;
}

std::vector<MeshCaster> prepare_mesh_casters(const Scene& scene) {
  std::vector<MeshCaster> casters;
  for (const Mesh& mesh : scene.meshes)
    casters.push_back(prepare_mesh_caster(mesh.report.shadow_method(), mesh.positions, mesh.triangles));
  return casters;
}

}  // namespace umbra
