#include "mesh/topology/edge_table.hpp"

#include <algorithm>

namespace umbra {

EdgeTable build_edge_table(const std::vector<std::array<uint32_t, 3>>& triangles, size_t vertex_count) {
  // Each directed edge a -> b of face t, filed under min(a, b) as
  // (max(a, b), t << 1 | a < b).
  std::vector<uint32_t> bucket_start(vertex_count + 1, 0);
  for (const auto& tri : triangles)
    for (int i = 0; i < 3; ++i) ++bucket_start[std::min(tri[size_t(i)], tri[size_t((i + 1) % 3)]) + 1];
  for (size_t v = 0; v < vertex_count; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<uint64_t> filed(bucket_start.back());  // (other vertex << 32) | use
  {
    std::vector<uint32_t> next(bucket_start.begin(), bucket_start.end() - 1);
    for (uint32_t t = 0; t < triangles.size(); ++t)
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = triangles[t][size_t(i)], b = triangles[t][size_t((i + 1) % 3)];
        filed[next[std::min(a, b)]++] = uint64_t(std::max(a, b)) << 32 | (t << 1 | uint32_t(a < b));
      }
  }
  EdgeTable table;
  table.uses.reserve(filed.size());
  table.vertices.reserve(filed.size() / 2 + 1);
  table.first_use.reserve(filed.size() / 2 + 2);
  for (size_t v = 0; v < vertex_count; ++v) {
    const auto begin = filed.begin() + bucket_start[v], end = filed.begin() + bucket_start[v + 1];
    // By the other vertex, then by face: insertion sort for the handful of
    // entries most vertices have, std::sort for the hub of a fan.
    if (end - begin > 32) {
      std::sort(begin, end);
    } else {
      for (auto it = begin + (begin != end); it < end; ++it)
        for (auto j = it; j > begin && *(j - 1) > *j; --j) std::iter_swap(j - 1, j);
    }
    for (auto it = begin; it != end; ++it) {
      const uint32_t other = uint32_t(*it >> 32);
      if (it == begin || uint32_t(*(it - 1) >> 32) != other) {
        if (it != begin) table.first_use.push_back(uint32_t(table.uses.size()));
        table.vertices.push_back({uint32_t(v), other});
      }
      table.uses.push_back(uint32_t(*it));
    }
    if (begin != end) table.first_use.push_back(uint32_t(table.uses.size()));
  }
  return table;
}

}  // namespace umbra
