#include "scene/mesh_placement.hpp"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace umbra {

MeshPlacement placement_of(const Mesh& m) {
  MeshPlacement placement;
  double fit_scale = 1.0;
  if (m.fit) {
    const glm::dvec3 lo = m.file_bounds_min, hi = m.file_bounds_max;
    placement.fit_centre = lo / 2.0 + hi / 2.0;  // halves first: lo + hi may overflow where each does not
    fit_scale = 2.0 / std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  }
  placement.scale = m.scale * fit_scale;
  placement.rotation = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(m.rotation_deg), glm::normalize(m.rotation_axis)));
  placement.translation = m.translation;
  return placement;
}

}  // namespace umbra
