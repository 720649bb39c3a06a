#pragma once
// What the renderer needs of a mesh's edges, taken from the check's own pass
// over them rather than from a second one: the edge table of the analysed
// triangles, as they were turned, and their closed components, equal to what
// build_edge_table and find_closed_components make of those triangles. Only
// for a mesh whose faces in the topology are all triangles, so that faces
// and triangles are one to one (a polygon's diagonals are edges the check
// never saw); the renderer builds both itself for any other.

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/topology/closed_components.hpp"
#include "mesh/topology/edge_table.hpp"

namespace umbra {

struct TriangleTopology {
  EdgeTable edges;
  ClosedComponents components;
};

// `face_edges` is the check's edge table over the file's faces (each use
// face << 1 | 1 when the face, as written, runs from the edge's smaller
// vertex to its larger). Triangle t comes from face triangle_face[t] and runs
// against it when turned[t]; component_of_triangle numbers the check's
// components (below component_count). `several_fans` marks the vertices
// whose corners form more than one fan; `border_loops` counts the border's
// connected pieces.
TriangleTopology triangle_topology(EdgeTable face_edges, const std::vector<std::array<uint32_t, 3>>& triangles,
                                   const std::vector<uint32_t>& triangle_face, const std::vector<uint8_t>& turned,
                                   const std::vector<uint32_t>& component_of_triangle, size_t component_count,
                                   const std::vector<uint8_t>& several_fans, size_t border_loops);

}  // namespace umbra
