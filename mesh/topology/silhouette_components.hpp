#pragma once
// Which parts of a triangle mesh cast their shadow from a silhouette: per
// component, as casts_from_silhouette (component_shape.hpp) decides, with
// counts of what keeps the other components from it, for a one-phrase
// explanation. The renderer takes this from the check's report
// (mesh/check/triangle_topology); find_silhouette_components makes it from bare
// triangles, as they are, for tests, benchmarks and the fuzzers.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/topology/edge_table.hpp"

namespace umbra {

struct SilhouetteComponents {
  // silhouette_face[t] = 1 when face t's component (faces joined across any
  // edge) casts from its silhouette: casts_from_silhouette.
  std::vector<uint8_t> silhouette_face;
  size_t components = 0;
  size_t silhouette_components = 0;      // those that cast from their silhouette
  size_t border_edges = 0;           // one face
  size_t border_loops = 0;           // cycles of the border edges, per component (border_loops.hpp), summed
  size_t non_manifold_edges = 0;     // three or more faces
  size_t inconsistent_edges = 0;     // two faces running the same way
  size_t non_manifold_vertices = 0;  // two or more fans, on no non-manifold edge
  // Polygons' diagonals that, once triangulated, lie along another edge
  // (component_shape.hpp): non-manifold among the triangles, not among the
  // file's faces, and said apart so that a render words them as the check does.
  size_t overlapping_diagonals = 0;

  bool all_cast_from_silhouette() const { return silhouette_components == components && components > 0; }
  // "closed 2-manifold", or what is not: "open, 3 holes, 2 non-manifold edges".
  std::string phrase() const;
  // How such a mesh casts its shadow: "silhouette volume" (all closed),
  // "edge-multiplicity volume" (none), or which components get which.
  std::string volume_phrase() const;
};

// `edges` is build_edge_table(triangles, vertex_count).
SilhouetteComponents find_silhouette_components(const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeTable& edges,
                                        size_t vertex_count);

}  // namespace umbra
