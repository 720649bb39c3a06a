#pragma once
// What one component of a mesh (its faces joined across edges) is, and the
// one rule that decides how it casts its shadow. The check's report, the
// renderer's choice of volume, --explain, the warnings and the JSON's
// shadow_method all ask these two functions.

#include <cstddef>

namespace umbra {

// What a pass over a component's edges finds, of its faces as the renderer
// draws them (the check flips an orientable component's faces to agree).
struct ComponentShape {
  size_t border_edges = 0;        // one face
  size_t non_manifold_edges = 0;  // three or more faces
  size_t pinched_vertices = 0;    // two or more fans of its faces round one vertex, on no non-manifold edge
  bool oriented = false;          // every edge with two faces has them running along it in opposite directions
  // Diagonals of its polygons, as umbra triangulates them, that run along
  // another edge: non-manifold edges of the triangles drawn, not of the file.
  size_t overlapping_diagonals = 0;
};

// No border, two faces on every edge, one fan round every vertex: a closed
// 2-manifold, whatever its orientation. Components that touch only at a
// vertex are each judged on their own.
inline bool is_closed_2_manifold(const ComponentShape& c) {
  return c.border_edges == 0 && c.non_manifold_edges == 0 && c.pinched_vertices == 0;
}

// Ready for the silhouette path: a closed 2-manifold whose faces agree and
// whose triangles keep two faces on every edge, so that every edge links
// exactly two faces of opposite sense in the half-edge structure. Any other
// component casts an edge-multiplicity volume.
inline bool casts_from_silhouette(const ComponentShape& c) {
  return is_closed_2_manifold(c) && c.oriented && c.overlapping_diagonals == 0;
}

}  // namespace umbra
