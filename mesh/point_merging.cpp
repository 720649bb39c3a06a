#include "mesh/point_merging.hpp"

#include <algorithm>
#include <numeric>

namespace umbra {

MergedPoints merge_coincident_points(const std::vector<glm::dvec3>& points) {
  std::vector<uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), uint32_t(0));
  const auto less = [&](uint32_t a, uint32_t b) {
    const glm::dvec3& p = points[a];
    const glm::dvec3& q = points[b];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    if (p.z != q.z) return p.z < q.z;
    return a < b;  // the first in the file leads its group
  };
  std::sort(order.begin(), order.end(), less);

  // Each group's leader (its first point in the file) stands for the group.
  std::vector<uint32_t> leader(points.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const bool starts_group = i == 0 || points[order[i]] != points[order[i - 1]];
    leader[order[i]] = starts_group ? order[i] : leader[order[i - 1]];
  }
  MergedPoints merged;
  merged.vertex_of_point.resize(points.size());
  for (uint32_t p = 0; p < points.size(); ++p) {
    if (leader[p] == p) {
      merged.vertex_of_point[p] = uint32_t(merged.positions.size());
      merged.positions.push_back(points[p]);
      merged.first_point.push_back(p);
    } else {
      merged.vertex_of_point[p] = merged.vertex_of_point[leader[p]];  // the leader comes first in the file
    }
  }
  return merged;
}

}  // namespace umbra
