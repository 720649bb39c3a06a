#include "mesh/check/triangle_topology.hpp"

#include <algorithm>

namespace umbra {

TriangleTopology triangle_topology(EdgeTable face_edges, const std::vector<std::array<uint32_t, 3>>& triangles,
                                   const std::vector<uint32_t>& triangle_face, const std::vector<uint8_t>& turned,
                                   const std::vector<uint32_t>& component_of_triangle, size_t component_count,
                                   const std::vector<uint8_t>& several_fans, size_t border_loops) {
  TriangleTopology out;
  // Faces become triangles (in the same order, so each edge's uses stay
  // sorted), each use running as its triangle now does.
  std::vector<uint32_t> triangle_of_face(triangle_face.empty() ? 0 : triangle_face.back() + 1);  // faces come in order
  for (uint32_t t = 0; t < triangle_face.size(); ++t) triangle_of_face[triangle_face[t]] = t;
  for (uint32_t& use : face_edges.uses) {
    const uint32_t t = triangle_of_face[EdgeTable::face_of(use)];
    use = t << 1 | (uint32_t(EdgeTable::runs_forward(use)) ^ turned[t]);
  }
  out.edges = std::move(face_edges);
  const EdgeTable& edges = out.edges;

  // As find_closed_components decides: a component is closed unless it has
  // an edge that is not two faces running opposite ways, or a vertex of
  // several fans.
  ClosedComponents& c = out.components;
  std::vector<uint8_t> open(component_count, 0), irregular_vertex(several_fans.size(), 0);
  for (size_t e = 0; e < edges.size(); ++e) {
    const uint32_t* use = edges.uses.data() + edges.first_use[e];
    const uint32_t count = edges.use_count(e);
    if (count == 2 && EdgeTable::runs_forward(use[0]) != EdgeTable::runs_forward(use[1])) continue;
    irregular_vertex[edges.vertices[e][0]] = irregular_vertex[edges.vertices[e][1]] = 1;
    open[component_of_triangle[EdgeTable::face_of(use[0])]] = 1;
    if (count == 1) ++c.border_edges;
    else if (count == 2) ++c.inconsistent_edges;
    else ++c.non_manifold_edges;
  }
  for (size_t t = 0; t < triangles.size(); ++t)
    for (const uint32_t v : triangles[t])
      if (several_fans[v]) open[component_of_triangle[t]] = 1;
  for (size_t v = 0; v < several_fans.size(); ++v) c.non_manifold_vertices += several_fans[v] && !irregular_vertex[v];
  c.border_loops = border_loops;
  c.components = component_count;
  c.closed_components = size_t(std::count(open.begin(), open.end(), 0));
  c.closed_face.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) c.closed_face[t] = !open[component_of_triangle[t]];
  return out;
}

}  // namespace umbra
