#pragma once
// Every pair of overlapping boxes among many: a bounding volume hierarchy over
// the boxes in Morton order of their centres (Lauterbach et al., "Fast BVH
// Construction on GPUs", 2009), searched from every box in parallel with TBB.
// Boxes are closed, so boxes that only touch overlap; the search is complete.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

// An axis-aligned box in floats, rounded outward from the doubles it bounds,
// so that it contains their exact box (half the memory of doubles).
struct FloatBox {
  std::array<float, 3> lo, hi;
  bool overlaps(const FloatBox& o) const {
    return lo[0] <= o.hi[0] && o.lo[0] <= hi[0] && lo[1] <= o.hi[1] && o.lo[1] <= hi[1] && lo[2] <= o.hi[2] &&
           o.lo[2] <= hi[2];
  }
};
FloatBox enclosing_box(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Calls visit(i, j), i != j indices into `boxes`, once for every unordered
// pair whose boxes overlap, from several threads at once: visit must be safe
// to call concurrently. When a call returns false the search stops early
// (calls already under way finish) and the function returns false; it
// returns true when every pair was visited.
bool for_each_overlapping_pair(std::vector<FloatBox> boxes, const std::function<bool(uint32_t, uint32_t)>& visit);

}  // namespace umbra
