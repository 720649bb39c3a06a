#pragma once
// Pairs of faces that cross or touch other than along the vertices and edges
// they share, found with a hierarchy of boxes (box_overlaps) and CGAL's exact
// predicates.

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

struct SelfIntersections {
  size_t face_pairs = 0;
  std::vector<std::pair<uint32_t, uint32_t>> examples;  // the first few pairs, by face index
  std::vector<std::pair<uint32_t, uint32_t>> pairs;  // every pair, by face index, in order (examples are the first)
  bool complete = true;  // false when the time limit stopped the search
  double seconds = 0.0;
};

// `triangles` index `positions` (coincident points already merged, so a shared
// vertex has one index); `triangle_face` names each triangle's face, and two
// triangles of the same face are not tested against each other. Triangles
// whose corners are collinear are skipped (exact intersection tests are
// undefined for them; the check reports them as degenerate).
SelfIntersections find_self_intersections(const std::vector<glm::dvec3>& positions,
                                          const std::vector<std::array<uint32_t, 3>>& triangles,
                                          const std::vector<uint32_t>& triangle_face, double time_limit_seconds,
                                          size_t max_examples);

}  // namespace umbra
