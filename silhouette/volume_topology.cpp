#include "silhouette/volume_topology.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace umbra {

bool is_closed_and_consistently_oriented(const ShadowVolume& volume) {
  // Count each directed edge; closed and consistent means every directed edge
  // occurs once and so does its reverse.
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const auto& t : volume.triangles)
    for (int i = 0; i < 3; ++i) {
      if (t[i] >= volume.vertices.size()) return false;
      ++directed[{t[i], t[(i + 1) % 3]}];
    }
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != 1) return false;
  }
  return !volume.triangles.empty();
}

bool has_no_boundary(const ShadowVolume& volume) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;  // (smaller, larger) -> uses forward minus backward
  for (const auto& t : volume.triangles)
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = t[size_t(i)], b = t[size_t((i + 1) % 3)];
      if (a >= volume.vertices.size() || b >= volume.vertices.size()) return false;
      directed[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
    }
  for (const auto& [edge, balance] : directed)
    if (balance != 0) return false;
  return !volume.triangles.empty();
}

}  // namespace umbra
