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

}  // namespace umbra
