#pragma once
// Filling a triangle mesh's holes, for `umbra check --repair`: each border
// cycle triangulated (the least-area triangulation of its boundary, searched
// over its 3D Delaunay edges), refined to the density of the faces round it,
// and faired so that the patch continues the surface's curvature (Liepa,
// "Filling Holes in Meshes", 2003, as CGAL's Polygon Mesh Processing
// implements it).

#include <cstddef>
#include <vector>

#include "mesh/check/repair_mesh_type.hpp"

namespace umbra {

struct HoleFilling {
  size_t filled = 0;              // holes closed
  size_t triangles_added = 0;     // by the filled holes' patches
  size_t faired_roughly = 0;      // filled, but the fairing's solver failed: the refined patch kept as it is
  std::vector<size_t> too_large;  // the edges of each hole left for having more than the bound
  std::vector<size_t> failed;     // the edges of each hole no triangulation was found for
  std::vector<size_t> touching;   // the edges of each hole left for passing twice through a point
};

// Fills every hole of `mesh` (a triangle mesh) with at most `max_edges`
// edges round it, but one whose border passes twice through a point (a
// patch would meet itself there); the others stay open.
HoleFilling fill_holes(repair::SurfaceMesh& mesh, size_t max_edges);

}  // namespace umbra
