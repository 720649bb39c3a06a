#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "silhouette/shadow_volume.hpp"

namespace umbra {

// The shadow volume of a convex planar polygon lit by a point light.
// Requires: `loop` is convex, planar, and counter-clockwise seen from `light`
// (its normal points to the light's side). Side quads are the polygon's edges
// extruded to infinity away from the light; the light cap is the polygon (a
// fan), the dark cap its image at infinity. The result is closed and oriented
// outward.
ShadowVolume extrude_to_infinity(const std::vector<glm::dvec3>& loop, const glm::dvec3& light);

}  // namespace umbra
