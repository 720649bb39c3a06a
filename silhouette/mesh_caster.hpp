#pragma once
// What each mesh of a scene needs to cast shadows, prepared once per scene:
// the shadow method its check chose, and for the silhouette method the
// adjacency that every light and frame then reads.

#include <vector>

#include "mesh/scene.hpp"
#include "silhouette/mesh_adjacency.hpp"

namespace umbra {

struct MeshCaster {
  ShadowMethod method = ShadowMethod::kPerTriangle;
  MeshAdjacency adjacency;  // filled for ShadowMethod::kSilhouette only
};

// One per scene.meshes entry, in order.
std::vector<MeshCaster> prepare_mesh_casters(const Scene& scene);

}  // namespace umbra
