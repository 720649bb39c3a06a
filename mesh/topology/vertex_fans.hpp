#pragma once
// A vertex's fans: the groups of its corners joined across the manifold
// edges round it. A vertex with more than one is non-manifold; a component
// that holds two fans of one vertex is pinched there. The one definition
// that the check (mesh/check/components) and the renderer's choice of
// volume (silhouette_components) both count with.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace umbra {

struct VertexFans {
  std::vector<uint8_t> several_fans;  // per vertex: its corners make more than one fan
  // One entry per pinch, naming the component pinched: a vertex on no
  // non-manifold edge (those are counted with the edge) two or more of whose
  // fans lie in that component, counted once however many it has there.
  std::vector<uint32_t> pinched_components;
};

// `for_each_corner(visit)` calls visit(vertex, component, fan) for every
// corner of the faces counted, with any ids for components and fans;
// it is called twice.
template <typename ForEachCorner>
VertexFans count_vertex_fans(size_t vertex_count, const std::vector<uint8_t>& on_non_manifold_edge, ForEachCorner&& for_each_corner) {
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  VertexFans out;
  out.several_fans.assign(vertex_count, 0);
  std::vector<uint32_t> fan_of_vertex(vertex_count, kNone);
  for_each_corner([&](uint32_t v, uint32_t, uint32_t fan) {
    if (fan_of_vertex[v] == kNone) fan_of_vertex[v] = fan;
    else if (fan_of_vertex[v] != fan) out.several_fans[v] = 1;
  });
  std::vector<std::array<uint32_t, 3>> vertex_fans;  // (vertex, component, fan) of the non-manifold vertices' corners
  for_each_corner([&](uint32_t v, uint32_t component, uint32_t fan) {
    if (out.several_fans[v] && !on_non_manifold_edge[v]) vertex_fans.push_back({v, component, fan});
  });
  std::sort(vertex_fans.begin(), vertex_fans.end());
  vertex_fans.erase(std::unique(vertex_fans.begin(), vertex_fans.end()), vertex_fans.end());
  const auto same_vertex_and_component = [&](size_t i, size_t j) {
    return vertex_fans[i][0] == vertex_fans[j][0] && vertex_fans[i][1] == vertex_fans[j][1];
  };
  for (size_t i = 1; i < vertex_fans.size(); ++i)
    if (same_vertex_and_component(i, i - 1) && (i < 2 || !same_vertex_and_component(i, i - 2)))
      out.pinched_components.push_back(vertex_fans[i][1]);
  return out;
}

}  // namespace umbra
