#pragma once
// What the renderer needs of a mesh's edges: the edge table of the analysed
// triangles, as they were turned, and which of their components cast from
// their silhouette, as the check's report decides them
// (ComponentReport::casts_from_silhouette). For a mesh whose faces in the
// topology are all triangles, the edge table comes from the check's own pass
// over the edges rather than a second one; a polygon's diagonals are edges
// that pass never saw, so any other mesh gets a pass over its triangles.

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/check/mesh_report.hpp"
#include "mesh/topology/silhouette_components.hpp"
#include "mesh/topology/edge_table.hpp"

namespace umbra {

struct TriangleTopology {
  EdgeTable edges;
  SilhouetteComponents components;
};

// `face_edges` is the check's edge table over the file's faces (each use
// face << 1 | 1 when the face, as written, runs from the edge's smaller
// vertex to its larger), all of them triangles. Triangle t comes from face
// triangle_face[t] and runs against it when turned[t].
EdgeTable triangle_edges_from_face_edges(EdgeTable face_edges, const std::vector<uint32_t>& triangle_face,
                                         const std::vector<uint8_t>& turned);

// `edges` is the triangles' edge table; component_of_triangle numbers the
// report's components. The counts are the report's, overlapping diagonals
// counted with the non-manifold edges, and the edges whose two triangles
// still run the same way (in non-orientable components).
SilhouetteComponents closed_components_of(const EdgeTable& edges, const std::vector<uint32_t>& component_of_triangle,
                                      const MeshReport& report);

}  // namespace umbra
