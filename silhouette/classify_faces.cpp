#include "silhouette/classify_faces.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "mesh/orientation.hpp"

namespace umbra {

void classify_faces(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing) {
  const size_t count = mesh.planes.size();
  facing.resize(count);
  const double light_distance = glm::length(light);
  for (size_t t = 0; t < count; ++t) {
    const MeshAdjacency::FacePlane& plane = mesh.planes[t];
    const double side = glm::dot(plane.normal, light) - plane.offset;
    const double bound = double(plane.error_per_light_distance) * light_distance + double(plane.error_constant);
    if (side > bound) {
      facing[t] = 1;
    } else if (side < -bound) {
      facing[t] = 0;
    } else {
      const auto& tri = mesh.triangles[t];
      facing[t] = orientation(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]], light) > 0;
    }
  }
}

}  // namespace umbra
