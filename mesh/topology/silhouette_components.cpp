#include "mesh/topology/silhouette_components.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "mesh/topology/border_loops.hpp"
#include "mesh/topology/component_shape.hpp"
#include "mesh/topology/union_find.hpp"
#include "mesh/topology/vertex_fans.hpp"

namespace umbra {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

std::string count_of(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Corner 3t + i is face t's corner at triangles[t][i].
uint32_t corner_at(const std::array<uint32_t, 3>& tri, uint32_t face, uint32_t vertex) {
  return 3 * face + (tri[0] == vertex ? 0 : tri[1] == vertex ? 1 : 2);
}

}  // namespace

std::string SilhouetteComponents::phrase() const {
  if (components == 0) return "no faces";
  std::string s;
  const auto add = [&s](const std::string& part) { s += (s.empty() ? "" : ", ") + part; };
  if (border_edges > 0) add("open, " + count_of(border_loops, "hole", "holes"));
  if (non_manifold_edges > 0) add(count_of(non_manifold_edges, "non-manifold edge", "non-manifold edges"));
  if (inconsistent_edges > 0) add(count_of(inconsistent_edges, "edge", "edges") + " with mixed winding");
  if (non_manifold_vertices > 0) add(count_of(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices"));
  if (overlapping_diagonals > 0)
    add(count_of(overlapping_diagonals, "diagonal", "diagonals") + " along another edge once triangulated");
  if (s.empty()) return "closed 2-manifold";
  if (silhouette_components > 0) s += "; " + std::to_string(silhouette_components) + " of " + std::to_string(components) +
                                   " components closed";
  return s;
}

std::string SilhouetteComponents::volume_phrase() const {
  if (silhouette_components == components) return "silhouette volume";
  if (silhouette_components == 0) return "edge-multiplicity volume";
  return "silhouette volume for its " + count_of(silhouette_components, "closed component", "closed components") +
         ", edge multiplicity for the other " + std::to_string(components - silhouette_components);
}

SilhouetteComponents find_silhouette_components(const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                        size_t vertex_count) {
  SilhouetteComponents result;
  const uint32_t face_count = uint32_t(triangles.size());
  // Faces join across any edge; corners round a vertex join into fans across
  // the edges with two faces, however those run (as the check joins them).
  UnionFind components(face_count), fans(3 * size_t(face_count));
  std::vector<BorderEdge> border;  // numbered by one face of each, until the components are known
  std::vector<uint8_t> on_non_manifold_edge(vertex_count, 0);
  std::vector<std::pair<uint32_t, ComponentShape>> found;  // (a face of the component, what one edge adds)
  for (size_t e = 0; e < edges.size(); ++e) {
    const uint32_t* use = edges.uses.data() + edges.first_use[e];
    const uint32_t count = edges.use_count(e);
    const auto [u, v] = edges.vertices[e];
    for (uint32_t k = 1; k < count; ++k) components.unite(EdgeTable::face_of(use[0]), EdgeTable::face_of(use[k]));
    const uint32_t x = EdgeTable::face_of(use[0]);
    if (count == 2) {
      const uint32_t y = EdgeTable::face_of(use[1]);
      fans.unite(corner_at(triangles[x], x, u), corner_at(triangles[y], y, u));
      fans.unite(corner_at(triangles[x], x, v), corner_at(triangles[y], y, v));
      if (EdgeTable::runs_forward(use[0]) == EdgeTable::runs_forward(use[1])) {
        ++result.inconsistent_edges;
        found.push_back({x, ComponentShape{0, 0, 0, false}});
      }
    } else if (count == 1) {
      ++result.border_edges;
      border.push_back({x, u, v});
      found.push_back({x, ComponentShape{1, 0, 0, true}});
    } else {
      ++result.non_manifold_edges;
      on_non_manifold_edge[u] = on_non_manifold_edge[v] = 1;
      found.push_back({x, ComponentShape{0, 1, 0, true}});
    }
  }
  // Border loops, per component (numbered by its root face).
  for (BorderEdge& e : border) e.component = components.find(e.component);
  for (const size_t loops : border_loops_per_component(std::move(border), face_count, vertex_count)) result.border_loops += loops;
  const VertexFans vertex_fans = count_vertex_fans(vertex_count, on_non_manifold_edge, [&](auto&& visit) {
    for (uint32_t t = 0; t < face_count; ++t)
      for (uint32_t i = 0; i < 3; ++i) visit(triangles[t][i], components.find(t), fans.find(3 * t + i));
  });
  for (const uint32_t root : vertex_fans.pinched_components) found.push_back({root, ComponentShape{0, 0, 1, true}});
  for (size_t v = 0; v < vertex_count; ++v) result.non_manifold_vertices += vertex_fans.several_fans[v] && !on_non_manifold_edge[v];
  // Each component's shape, summed from what was found, and the one rule.
  std::vector<ComponentShape> shape(face_count, ComponentShape{0, 0, 0, true});
  for (const auto& [face, part] : found) {
    ComponentShape& s = shape[components.find(face)];
    s.border_edges += part.border_edges;
    s.non_manifold_edges += part.non_manifold_edges;
    s.pinched_vertices += part.pinched_vertices;
    s.oriented = s.oriented && part.oriented;
  }
  std::vector<uint8_t> root_seen(face_count, 0);
  result.silhouette_face.resize(face_count);
  for (uint32_t t = 0; t < face_count; ++t) {
    const uint32_t root = components.find(t);
    const bool closed = casts_from_silhouette(shape[root]);
    result.silhouette_face[t] = closed;
    if (root_seen[root]) continue;
    root_seen[root] = 1;
    ++result.components;
    result.silhouette_components += closed;
  }
  return result;
}

}  // namespace umbra
