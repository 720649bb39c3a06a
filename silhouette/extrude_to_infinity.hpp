#pragma once

#include <optional>
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
//
// With `centre` (a point inside the polygon), both caps are fans round it and
// its image at infinity instead of fans from the first vertex. A sphere lit
// from just outside it has a tangent cone of nearly 90 degrees, whose
// directions at infinity lie almost in one plane: a fan from one of them makes
// triangles spanned by nearly opposite directions, which float clipping
// cannot resolve, while every triangle of a fan round the cone's axis spans
// a well-conditioned right angle.
ShadowVolume extrude_to_infinity(const std::vector<glm::dvec3>& loop, const glm::dvec3& light,
                                 const std::optional<glm::dvec3>& centre = std::nullopt);

}  // namespace umbra
