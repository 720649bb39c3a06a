#pragma once

#include <glm/vec3.hpp>

#include "silhouette/shadow_volume.hpp"

namespace umbra {

// The circle where rays from the light touch a sphere (docs/geometry.md).
struct TangentCircle {
  glm::dvec3 center{0.0};  // P = L + PL * LC / |LC|
  double radius = 0.0;     // r
  glm::dvec3 u{0.0}, v{0.0};  // perpendicular to LC, each of length r
};

// Requires the light strictly outside the sphere (|LC| > R); see
// require_lights_off_casters.
TangentCircle tangent_circle(const glm::dvec3& center, double radius, const glm::dvec3& light);

// The N-gon Q_k = P + cos(2 pi k / N) v + sin(2 pi k / N) u inscribed
// in the tangent circle, extruded to infinity, with the N-gon as light cap.
// Requires segments >= 3 and the light outside the sphere.
ShadowVolume sphere_volume(const glm::dvec3& center, double radius, const glm::dvec3& light, int segments);

}  // namespace umbra
