#include "silhouette/light_facing.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "silhouette/face_plane.hpp"

namespace umbra {

void classify_light_facing(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing) {
  const size_t count = mesh.planes.size();
  facing.resize(count);
  const double light_distance = glm::length(light);
  for (size_t t = 0; t < count; ++t) {
    const auto& tri = mesh.triangles[t];
    facing[t] = light_side(mesh.planes[t], mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]],
                           light, light_distance) > 0;
  }
}

}  // namespace umbra
