#include "silhouette/light_facing.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "silhouette/face_plane.hpp"
#include "silhouette/parallel_append.hpp"

namespace umbra {

void classify_light_facing(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing) {
  const size_t count = mesh.planes.size();
  facing.resize(count);
  const double light_distance = glm::length(light);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, kClassifyBlock), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t < r.end(); ++t) {
      const auto& tri = mesh.triangles[t];
      facing[t] = light_side(mesh.planes[t], mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]],
                             light, light_distance) > 0;
    }
  });
}

}  // namespace umbra
