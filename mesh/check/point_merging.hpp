#pragma once
// Points with equal coordinates are one vertex: STL repeats every point in
// each triangle, and other exporters split vertices at seams.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

struct MergedPoints {
  std::vector<glm::dvec3> positions;      // one per distinct coordinate triple, in order of first appearance
  std::vector<uint32_t> vertex_of_point;  // file point -> index into positions
  std::vector<uint32_t> first_point;      // position -> the first file point with it
};

// Exact equality, no tolerance: points that differ in the last bit stay apart
// (and the check reports the gap as a border, which it is).
MergedPoints merge_coincident_points(const std::vector<glm::dvec3>& points);

// For --repair --merge-tolerance: each point, in file order, joins a kept
// point within `tolerance` of it (distance at most tolerance), or is kept
// itself. A point never moves a kept one, so merges do not chain: two
// points 1.5 tolerances apart stay apart even with a third between them.
// Cells of the tolerance's size make each search look at 27 cells.
MergedPoints merge_nearby_points(const std::vector<glm::dvec3>& points, double tolerance);

}  // namespace umbra
