#pragma once
// What each mesh of a scene needs to cast shadows, prepared once per scene:
// the shadow method its check chose, and for the silhouette method the
// adjacency that every light and frame then reads.

#include <string>
#include <vector>

#include "mesh/scene.hpp"
#include "silhouette/mesh_adjacency.hpp"

namespace umbra {

struct MeshCaster {
  ShadowMethod method = ShadowMethod::kPerTriangle;
  MeshAdjacency adjacency;  // filled for ShadowMethod::kSilhouette only
  std::string reason;       // why the method differs from the check's, or empty
};

// The caster of one mesh: the check's method, except that a mesh whose
// polygons are a closed 2-manifold but whose triangulation is not (a
// non-planar polygon's diagonal that another face also uses) falls back to
// per-triangle volumes, which are right for any triangles.
MeshCaster prepare_mesh_caster(ShadowMethod checked, const std::vector<glm::dvec3>& positions,
                               const std::vector<std::array<uint32_t, 3>>& triangles);

// One per scene.meshes entry, in order.
std::vector<MeshCaster> prepare_mesh_casters(const Scene& scene);

}  // namespace umbra
