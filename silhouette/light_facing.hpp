#pragma once
// Which faces of a closed mesh face a light: the first step of finding its
// silhouette, once per light and frame.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "silhouette/mesh_adjacency.hpp"

namespace umbra {

// facing[t] = 1 when face t faces `light` (the light is strictly on the side
// its normal points to), else 0. The plane test decides where its rounding
// cannot change the sign; elsewhere the exact orientation predicate does, so
// a face whose plane passes through the light is always "not facing" and two
// faces never disagree about a light on their common plane.
void classify_light_facing(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing);

}  // namespace umbra
