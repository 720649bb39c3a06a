#include "silhouette/triangle_volume.hpp"

#include "mesh/predicates/orientation.hpp"
#include "silhouette/extrude_to_infinity.hpp"

namespace umbra {

std::optional<ShadowVolume> triangle_volume(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                            const glm::dvec3& light) {
  // The sign of (AB x AC) . AL (docs/geometry.md); zero also covers collinear vertices.
  const int side = orientation(a, b, c, light);
  if (side == 0) return std::nullopt;
  if (side > 0) return extrude_to_infinity({a, b, c}, light);
  return extrude_to_infinity({a, c, b}, light);
}

}  // namespace umbra
