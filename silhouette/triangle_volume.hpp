#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "silhouette/shadow_volume.hpp"

namespace umbra {

// The shadow volume of triangle abc lit from `light` (Crow 1977): side quads
// ABB'A', BCC'B', CAA'C' oriented by the sign of (AB x AC) . AL, so the volume
// is the same whatever the vertex order. None when the triangle casts no
// shadow: its vertices are collinear, or its plane contains the light (decided
// exactly, so a triangle seen edge-on never gets a sliver of either sign).
std::optional<ShadowVolume> triangle_volume(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                            const glm::dvec3& light);

}  // namespace umbra
