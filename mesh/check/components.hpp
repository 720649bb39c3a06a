#pragma once
// The mesh check's components: sets of faces joined across edges, numbered
// in order of their first face, with what each holds; the vertices whose
// faces form more than one fan; and the border's loops.

#include <cstdint>
#include <vector>

#include "mesh/check/edge_groups.hpp"
#include "mesh/check/face_classes.hpp"
#include "mesh/check/mesh_report.hpp"
#include "mesh/topology/vertex_fans.hpp"

namespace umbra {

struct ComponentLabels {
  std::vector<uint32_t> of_face;          // a face's component; none for faces outside the topology
  std::vector<ComponentReport> reports;   // faces, edges, border_edges and non_manifold_edges counted
  std::vector<uint8_t> conflict;          // per component: faces no flips can make agree
  std::vector<size_t> inconsistent;       // per component: edges two faces run the same way
};
ComponentLabels label_components(const FaceClasses& faces, EdgeGroups& groups);

// Each component's vertices, and its fans as mesh/topology/vertex_fans
// counts them.
struct ComponentVertices {
  std::vector<size_t> vertices;           // per component
  std::vector<size_t> pinched_vertices;   // per component: vertices two of whose fans lie in it (on no non-manifold edge)
  std::vector<uint32_t> non_manifold_vertices;  // in vertex order; vertices on a non-manifold edge are counted with the edge
  std::vector<uint8_t> several_fans;      // per vertex: its corners form more than one fan
  size_t topology_vertices = 0;           // vertices of the faces in the topology
};
ComponentVertices find_vertex_fans(const PolygonSoup& soup, const FaceClasses& faces, EdgeGroups& groups,
                            const ComponentLabels& labels, size_t vertex_count);

// The holes of each component (border_loops_per_component).
struct BorderLoops {
  size_t loops = 0;
  std::vector<size_t> per_component;
};
BorderLoops count_border_loops(const EdgeGroups& groups, const ComponentLabels& labels, size_t vertex_count);

}  // namespace umbra
