#pragma once
// Filling a triangle mesh's holes, for `umbra check --repair`: each border
// cycle triangulated (the least-area triangulation of its boundary, searched
// over its 3D Delaunay edges), refined to the density of the faces round it,
// and faired so that the patch continues the surface's curvature (Liepa,
// "Filling Holes in Meshes", 2003, as CGAL's Polygon Mesh Processing
// implements it).

#include <array>
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
  size_t on_flat_parts = 0;       // holes left in flat parts (a panel, a sheet), which have no inside to close
  size_t lobes = 0;               // of holes whose border passes twice through a point, filled by add_lobe_patches
  size_t filled_flat = 0;         // filled by the border's least-area triangulation alone: the faired patch crossed the mesh
  size_t crossing = 0;            // left open: each patch, faired and flat, crossed the mesh
};

// Fills every hole of `mesh` (a triangle mesh) with at most `max_edges`
// edges round it; the others stay open. Where `refuse_crossing_patches`, a
// patch that crosses the part it closes is taken out again and the
// border's least-area triangulation tried alone; where that crosses too,
// the hole stays open. A hole whose border passes twice
// through one point (two copies of it, split where faces met there alone)
// is cut at that point into lobes, each triangulated on its own; their
// triangles, which meet both copies, are left for add_lobe_patches.
HoleFilling fill_holes(repair::SurfaceMesh& mesh, size_t max_edges, std::vector<std::array<repair::Point, 3>>& lobe_triangles,
                       bool refuse_crossing_patches = false);

// `mesh` rebuilt with `triangles` added and each point's copies merged
// where the new faces close the fans they had split (split again where they
// do not); then the added faces refined and faired, as fill_holes fairs a
// patch. Returns the triangles the patches became.
size_t add_lobe_patches(repair::SurfaceMesh& mesh, const std::vector<std::array<repair::Point, 3>>& triangles);

}  // namespace umbra
