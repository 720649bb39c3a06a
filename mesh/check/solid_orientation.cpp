#include "mesh/check/solid_orientation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <tbb/enumerable_thread_specific.h>

#include "mesh/check/box_overlaps.hpp"

namespace umbra {
namespace {

// The solid angle of triangle abc seen from the origin, signed positive when
// abc turns counter-clockwise seen from outside (Van Oosterom and Strackee 1983).
double solid_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  return 2.0 * std::atan2(glm::dot(a, glm::cross(b, c)),
                          la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la);
}

}  // namespace

ShellFacing facing_of_closed_components(const std::vector<glm::dvec3>& positions,
                                                const std::vector<std::array<uint32_t, 3>>& triangles,
                                                const std::vector<uint32_t>& component_of, size_t count,
                                                const std::vector<uint8_t>& closed, const std::vector<uint8_t>& tangled,
                                                const std::vector<uint8_t>* reversed) {
  // Corner k of triangle t, as read turned round where `reversed` says so.
  const auto corner = [&](size_t t, size_t k) { return triangles[t][reversed && (*reversed)[t] && k ? 3 - k : k]; };
  std::vector<glm::dvec3> lo(count, glm::dvec3(1e300)), hi(count, glm::dvec3(-1e300));
  std::vector<uint8_t> has_faces(count, 0);
  for (uint32_t t = 0; t < triangles.size(); ++t) {
    const uint32_t c = component_of[t];
    has_faces[c] = 1;
    for (const uint32_t v : triangles[t]) lo[c] = glm::min(lo[c], positions[v]), hi[c] = glm::max(hi[c], positions[v]);
  }
  // Each component's volume, summed with its points scaled by a power of
  // two (exact) where its size is beyond what a product of three holds (a
  // part 1e200 wide cubes past a double's range, to NaN; one 1e-200 wide
  // underflows to 0), so that its sign, which decides the facing, is right;
  // then scaled back, to infinity or 0 where it must.
  std::vector<int> shift(count, 0);
  for (uint32_t c = 0; c < count; ++c) {
    const glm::dvec3 size = hi[c] - lo[c];
    const double extent = std::max({size.x, size.y, size.z});
    if (has_faces[c] && extent > 0.0 && std::isfinite(extent) && !(extent < 0x1p64 && extent > 0x1p-64)) shift[c] = std::ilogb(extent);
  }
  std::vector<double> volume(count, 0.0);
  for (uint32_t t = 0; t < triangles.size(); ++t) {
    const uint32_t c = component_of[t];
    if (!closed[c]) continue;
    const glm::dvec3 centre = 0.5 * lo[c] + 0.5 * hi[c];
    const auto relative = [&](size_t k) {
      const glm::dvec3 d = positions[corner(t, k)] - centre;
      return glm::dvec3(std::ldexp(d.x, -shift[c]), std::ldexp(d.y, -shift[c]), std::ldexp(d.z, -shift[c]));
    };
    const glm::dvec3 a = relative(0), b = relative(1), e = relative(2);
    volume[c] += glm::dot(a, glm::cross(b, e)) / 6.0;
  }
  // Nesting is tested only between closed components one of whose boxes
  // holds the other: only those need their triangles listed (a single
  // shell, however large, needs none). The pairs come from a search of the
  // closed components' boxes, not a test of every pair: a scan's debris can
  // be 100,000 components.
  const auto holds = [&](size_t d, size_t c) {  // d's box holds c's
    return !glm::any(glm::lessThan(lo[c], lo[d])) && !glm::any(glm::greaterThan(hi[c], hi[d]));
  };
  std::vector<uint32_t> shells;  // the closed components with faces
  for (uint32_t c = 0; c < count; ++c)
    if (closed[c] && has_faces[c]) shells.push_back(c);
  std::vector<std::pair<uint32_t, uint32_t>> nested;  // (c, d): d's box holds c's, sorted
  {
    std::vector<FloatBox> boxes(shells.size());
    for (size_t i = 0; i < shells.size(); ++i)  // the box round its two corners, rounded outward to floats
      boxes[i] = enclosing_box(lo[shells[i]], hi[shells[i]], hi[shells[i]]);
    tbb::enumerable_thread_specific<std::vector<std::pair<uint32_t, uint32_t>>> found;
    for_each_overlapping_pair(boxes, [&](const std::pair<uint32_t, uint32_t>* pairs, size_t n) {
      std::vector<std::pair<uint32_t, uint32_t>>& mine = found.local();
      for (size_t k = 0; k < n; ++k) {
        const uint32_t a = shells[pairs[k].first], b = shells[pairs[k].second];
        if (holds(a, b)) mine.emplace_back(b, a);
        if (holds(b, a)) mine.emplace_back(a, b);
      }
      return true;
    });
    for (const auto& mine : found) nested.insert(nested.end(), mine.begin(), mine.end());
    std::sort(nested.begin(), nested.end());
  }
  std::vector<uint8_t> listed(count, 0);
  for (const auto& [c, d] : nested) listed[c] = listed[d] = 1;
  std::vector<std::vector<uint32_t>> faces(count);
  for (uint32_t t = 0; t < triangles.size(); ++t)
    if (listed[component_of[t]]) faces[component_of[t]].push_back(t);
  // How many closed components wind round component c: its depth.
  const auto winds_round = [&](size_t d, const glm::dvec3& p) {
    double sum = 0.0;
    for (const uint32_t t : faces[d])
      sum += solid_angle(positions[corner(t, 0)] - p, positions[corner(t, 1)] - p, positions[corner(t, 2)] - p);
    return std::abs(sum) / (4.0 * M_PI);
  };
  std::vector<Facing> facing(count, Facing::kRight);
  for (size_t i = 0, next = 0; i < shells.size(); ++i) {
    const uint32_t c = shells[i];
    bool decided = !tangled[c];
    int depth = 0;
    for (; next < nested.size() && nested[next].first == c; ++next) {
      const uint32_t d = nested[next].second;
      if (!decided || tangled[d]) {
        decided = false;
        continue;
      }
      // A vertex of c off d's surface (c and d cross nowhere, but may touch
      // at a point): the winding there is 0 or 1. None among 24: undecided.
      double w = 0.5;
      for (size_t k = 0; k < faces[c].size() && k < 24 && std::abs(w - 0.5) < 0.25; ++k)
        w = winds_round(d, positions[corner(faces[c][k], k % 3)]);
      decided = std::abs(w - 0.5) >= 0.25;
      depth += w > 0.5;
    }
    if (!decided) facing[c] = Facing::kUndecided;
    else if ((volume[c] > 0.0) != (depth % 2 == 0)) facing[c] = Facing::kWrong;
  }
  for (uint32_t c = 0; c < count; ++c) volume[c] = std::ldexp(volume[c], 3 * shift[c]);
  return {std::move(facing), std::move(volume)};
}

}  // namespace umbra
