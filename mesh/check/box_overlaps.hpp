#pragma once
// Every pair of overlapping boxes among many: a bounding volume hierarchy over
// the boxes in Morton order of their centres (Lauterbach et al., "Fast BVH
// Construction on GPUs", 2009), searched from every box in parallel with TBB.
// Boxes are closed, so boxes that only touch overlap; the search is complete.

#include <array>
#include <cstdint>
#include <functional>
#include <utility>
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

// Takes the overlapping pairs (i, j), i != j indices into the boxes, in
// batches: called from several threads at once, so it must be safe to call
// concurrently. Returning false stops the search.
using OverlapVisitor = std::function<bool(const std::pair<uint32_t, uint32_t>* pairs, size_t count)>;

// The box of each index below a count, asked once each, from several
// threads at once.
using BoxOf = std::function<FloatBox(uint32_t)>;

// Pairs of triangles' boxes that need no visit: those whose triangles share
// a vertex marked in `vertices`. They are left out as the search finds them,
// which is far cheaper than handing them over when nearly every overlapping
// pair is a pair of neighbours.
struct SharedVertexSkip {
  std::function<std::array<uint32_t, 3>(uint32_t)> corners_of;  // box index to its triangle's vertices; empty: skip nothing
  const std::vector<uint8_t>* vertices = nullptr;  // per vertex, 1 to skip the pairs sharing it
};

// Hands every unordered pair of overlapping boxes to `visit` once, but for
// those `skip` leaves out. `bounds` should hold every box; it only steers the
// order of the search, never what it finds. Returns true when every pair was
// visited, false when a call returned false and the search stopped early
// (calls already under way finish).
bool for_each_overlapping_pair(size_t count, const FloatBox& bounds, const BoxOf& box_of, const OverlapVisitor& visit,
                               const SharedVertexSkip& skip = {});
bool for_each_overlapping_pair(const std::vector<FloatBox>& boxes, const OverlapVisitor& visit);

}  // namespace umbra
