#include "mesh/check/triangle_topology.hpp"


namespace umbra {

EdgeTable triangle_edges_from_face_edges(EdgeTable face_edges, const std::vector<uint32_t>& triangle_face,
                                         const std::vector<uint8_t>& turned) {
  // Faces become triangles (in the same order, so each edge's uses stay
  // sorted), each use running as its triangle now does.
  std::vector<uint32_t> triangle_of_face(triangle_face.empty() ? 0 : triangle_face.back() + 1);  // faces come in order
  for (uint32_t t = 0; t < triangle_face.size(); ++t) triangle_of_face[triangle_face[t]] = t;
  for (uint32_t& use : face_edges.uses) {
    const uint32_t t = triangle_of_face[EdgeTable::face_of(use)];
    use = t << 1 | (uint32_t(EdgeTable::runs_forward(use)) ^ turned[t]);
  }
  return face_edges;
}

SilhouetteComponents closed_components_of(const EdgeTable& edges, const std::vector<uint32_t>& component_of_triangle,
                                      const MeshReport& report) {
  SilhouetteComponents c;
  c.components = report.components.size();
  c.silhouette_components = report.silhouette_components();
  c.border_edges = report.border_edges;
  c.border_loops = report.border_loops;
  c.non_manifold_edges = report.non_manifold_edges;
  for (const ComponentReport& r : report.components) c.overlapping_diagonals += r.overlapping_diagonals;
  c.non_manifold_vertices = report.non_manifold_vertices;
  for (size_t e = 0; e < edges.size(); ++e) {
    const uint32_t* use = edges.uses.data() + edges.first_use[e];
    c.inconsistent_edges += edges.use_count(e) == 2 && EdgeTable::runs_forward(use[0]) == EdgeTable::runs_forward(use[1]);
  }
  c.silhouette_face.resize(component_of_triangle.size());
  for (size_t t = 0; t < component_of_triangle.size(); ++t)
    c.silhouette_face[t] = report.components[component_of_triangle[t]].casts_from_silhouette();
  return c;
}

}  // namespace umbra
