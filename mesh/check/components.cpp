#include "mesh/check/components.hpp"

#include <algorithm>
#include <limits>

#include "mesh/topology/border_loops.hpp"

namespace umbra {
namespace {
constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
}  // namespace

ComponentLabels label_components(const FaceClasses& faces, EdgeGroups& groups) {
  const size_t face_count = faces.repeats_vertex.size();
  ComponentLabels labels;
  labels.of_face.assign(face_count, kNone);
  std::vector<uint32_t> component_of_root(face_count, kNone);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    uint32_t& id = component_of_root[groups.components.find(f)];
    if (id == kNone) {
      id = uint32_t(labels.reports.size());
      labels.reports.emplace_back();
    }
    labels.of_face[f] = id;
    ++labels.reports[id].faces;
  }
  const size_t count = labels.reports.size();
  labels.conflict.assign(count, 0);
  labels.inconsistent.assign(count, 0);
  for (const EdgeRun& e : groups.edges) {
    ComponentReport& c = labels.reports[labels.of_face[e.face]];
    ++c.edges;
    if (e.uses == 1) ++c.border_edges;
    if (e.uses > 2) ++c.non_manifold_edges;
  }
  for (uint32_t f : groups.inconsistent_edge_faces) ++labels.inconsistent[labels.of_face[f]];
  for (uint32_t f = 0; f < face_count; ++f)
    if (groups.orientation_conflict[f]) labels.conflict[labels.of_face[f]] = 1;
  return labels;
}

ComponentVertices find_vertex_fans(const PolygonSoup& soup, const FaceClasses& faces, EdgeGroups& groups,
                                   const ComponentLabels& labels, size_t vertex_count) {
  const uint32_t face_count = uint32_t(faces.repeats_vertex.size());
  ComponentVertices out;
  out.vertices.assign(labels.reports.size(), 0);
  out.pinched_vertices.assign(labels.reports.size(), 0);
  std::vector<uint32_t> component_of_vertex(vertex_count, kNone);
  std::vector<uint64_t> vertex_in_other_component;  // (component << 32) | vertex: only where components touch
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    const uint32_t component = labels.of_face[f];
    for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c) {
      const uint32_t v = faces.corners[c];
      if (component_of_vertex[v] == kNone) {
        component_of_vertex[v] = component;
        ++out.vertices[component];
        ++out.topology_vertices;
      } else if (component_of_vertex[v] != component) {
        vertex_in_other_component.push_back((uint64_t(component) << 32) | v);
      }
    }
  }
  std::sort(vertex_in_other_component.begin(), vertex_in_other_component.end());
  vertex_in_other_component.erase(std::unique(vertex_in_other_component.begin(), vertex_in_other_component.end()),
                                  vertex_in_other_component.end());
  for (uint64_t cv : vertex_in_other_component) ++out.vertices[cv >> 32];
  VertexFans fans = count_vertex_fans(vertex_count, groups.on_non_manifold_edge, [&](auto&& visit) {
    for (uint32_t f = 0; f < face_count; ++f)
      if (faces.in_topology(f))
        for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c)
          visit(faces.corners[c], labels.of_face[f], groups.fans.find(c));
  });
  for (uint32_t v = 0; v < vertex_count; ++v)
    if (fans.several_fans[v] && !groups.on_non_manifold_edge[v]) out.non_manifold_vertices.push_back(v);
  for (const uint32_t component : fans.pinched_components) ++out.pinched_vertices[component];
  out.several_fans = std::move(fans.several_fans);
  return out;
}

BorderLoops count_border_loops(const EdgeGroups& groups, const ComponentLabels& labels, size_t vertex_count) {
  std::vector<BorderEdge> border;
  for (const EdgeRun& e : groups.edges)
    if (e.uses == 1) border.push_back({labels.of_face[e.face], e.a, e.b});
  BorderLoops out;
  out.per_component = border_loops_per_component(std::move(border), labels.reports.size(), vertex_count);
  for (const size_t loops : out.per_component) out.loops += loops;
  return out;
}

}  // namespace umbra
