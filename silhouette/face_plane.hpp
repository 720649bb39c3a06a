#pragma once
// A face's plane with a bound on its rounding, so that the side a light lies
// on is decided by one dot product unless the light is within rounding of the
// plane, and then by the exact orientation predicate.

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "mesh/predicates/orientation.hpp"

namespace umbra {

// n . x - offset has the sign of orient3d(a, b, c, x) for n = (b - a) x (c - a),
// up to the rounding bound error_per_light_distance * |x| + error_constant
// (both rounded up).
struct FacePlane {
  glm::dvec3 normal;
  double offset;
  float error_per_light_distance;
  float error_constant;
};

FacePlane face_plane(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// +1 when `light` is strictly on the side face abc's normal points to, -1 on
// the other side, 0 in its plane (or abc is degenerate): the exact sign of
// orient3d(a, b, c, light), from the plane test where its rounding cannot
// change it. `light_distance` is |light|.
inline int light_side(const FacePlane& plane, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                      const glm::dvec3& light, double light_distance) {
  const double side = glm::dot(plane.normal, light) - plane.offset;
  const double bound = double(plane.error_per_light_distance) * light_distance + double(plane.error_constant);
  if (side > bound) return 1;
  if (side < -bound) return -1;
  return orientation(a, b, c, light);
}

}  // namespace umbra
