#pragma once
// Which parts of a triangle mesh can cast their shadow from a silhouette:
// the components that are closed, consistently oriented 2-manifolds. Decided
// from the edge table alone, with counts of what keeps the other components
// from it, for a one-phrase explanation.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/topology/edge_table.hpp"

namespace umbra {

struct ClosedComponents {
  // closed_face[t] = 1 when face t's component (faces joined across any
  // edge) has exactly two faces on every edge, running along it in opposite
  // directions, and one fan of faces round every vertex.
  std::vector<uint8_t> closed_face;
  size_t components = 0;
  size_t closed_components = 0;
  size_t border_edges = 0;           // one face
  size_t border_loops = 0;           // cycles of the border edges, per component (border_loops.hpp), summed
  size_t non_manifold_edges = 0;     // three or more faces
  size_t inconsistent_edges = 0;     // two faces running the same way
  size_t non_manifold_vertices = 0;  // two or more fans, on no edge counted above

  bool all_closed() const { return closed_components == components && components > 0; }
  // "closed 2-manifold", or what is not: "open, 3 holes, 2 non-manifold edges".
  std::string phrase() const;
  // How such a mesh casts its shadow: "silhouette volume" (all closed),
  // "edge-multiplicity volume" (none), or which components get which.
  std::string volume_phrase() const;
};

// `edges` is build_edge_table(triangles, vertex_count).
ClosedComponents find_closed_components(const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                        size_t vertex_count);

}  // namespace umbra
