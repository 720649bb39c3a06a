#include "silhouette/mesh_caster.hpp"

#include "mesh/half_edge_mesh.hpp"

namespace umbra {

std::vector<MeshCaster> prepare_mesh_casters(const Scene& scene) {
  std::vector<MeshCaster> casters;
  for (const Mesh& mesh : scene.meshes) {
    MeshCaster caster;
    caster.method = mesh.report.shadow_method();
    if (caster.method == ShadowMethod::kSilhouette)
      caster.adjacency = build_mesh_adjacency(build_half_edge_mesh(mesh.positions, mesh.triangles));
    casters.push_back(std::move(caster));
  }
  return casters;
}

}  // namespace umbra
