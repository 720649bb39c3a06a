#pragma once
// Which way each closed component of a mesh should face: away from the solid
// it bounds. A shell nested in an even number of others (0, 2, ...) bounds
// solid inside it and should enclose positive volume; one nested in an odd
// number bounds a cavity (the inner shell of a hollow solid) and should
// enclose negative volume, as CGAL's orient_to_bound_a_volume decides.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

// wrong[c] = 1 when closed component c faces the wrong way (into its solid);
// 0 for one that faces the right way and for every component that is not
// closed. `component_of[t]` numbers triangle t's component, below `count`;
// `closed[c]` says which are closed and consistently oriented. With
// `reversed`, triangle t is read turned round (its corners 1 and 2 swapped)
// where reversed[t] is set.
//
// Volumes are summed about the centre of each component's own box, so a
// small solid far from the origin keeps its sign (summed about the origin,
// 1e9 away, its terms cancel to noise). Nesting is decided by the winding
// number of each other closed component round a vertex of this one, summed
// from solid angles (Van Oosterom and Strackee 1983), only where that
// component's box holds this one's.
std::vector<uint8_t> wrongly_facing_closed_components(const std::vector<glm::dvec3>& positions,
                                                      const std::vector<std::array<uint32_t, 3>>& triangles,
                                                      const std::vector<uint32_t>& component_of, size_t count,
                                                      const std::vector<uint8_t>& closed,
                                                      const std::vector<uint8_t>* reversed = nullptr);

}  // namespace umbra
