#include "mesh/topology/border_loops.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "mesh/topology/union_find.hpp"

namespace umbra {

std::vector<size_t> border_loops_per_component(std::vector<BorderEdge> border, size_t component_count, size_t vertex_count) {
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::vector<size_t> loops(component_count, 0);
  std::sort(border.begin(), border.end(), [](const BorderEdge& x, const BorderEdge& y) { return x.component < y.component; });
  // Each component's vertices are numbered afresh, so that components that
  // share a vertex share no piece of border.
  std::vector<uint32_t> local(vertex_count, kNone);
  UnionFind pieces(2 * border.size());  // at most two new vertices an edge
  for (size_t first = 0, next = 0; first < border.size(); first = next) {
    const uint32_t c = border[first].component;
    const uint32_t base = uint32_t(2 * first);
    uint32_t vertices = 0;
    for (next = first; next < border.size() && border[next].component == c; ++next) {
      for (const uint32_t v : {border[next].a, border[next].b})
        if (local[v] == kNone) local[v] = base + vertices++;
      pieces.unite(local[border[next].a], local[border[next].b]);
    }
    // Per piece, E - V + 1 cycles, and at least one: a piece that is no
    // cycle (a fin's border, ending on a non-manifold edge) is still a hole.
    std::vector<uint32_t> piece_edges(vertices, 0), piece_vertices(vertices, 0);
    for (size_t k = first; k < next; ++k) ++piece_edges[pieces.find(local[border[k].a]) - base];
    for (uint32_t v = base; v < base + vertices; ++v) ++piece_vertices[pieces.find(v) - base];
    for (uint32_t r = 0; r < vertices; ++r)
      if (piece_vertices[r] > 0) loops[c] += std::max<int64_t>(1, int64_t(piece_edges[r]) - int64_t(piece_vertices[r]) + 1);
    for (size_t k = first; k < next; ++k) local[border[k].a] = local[border[k].b] = kNone;
  }
  return loops;
}

}  // namespace umbra
