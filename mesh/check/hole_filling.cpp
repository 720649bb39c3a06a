#include "mesh/check/hole_filling.hpp"

#include <algorithm>
#include <iterator>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

namespace umbra {

namespace PMP = CGAL::Polygon_mesh_processing;
using repair::SurfaceMesh;

HoleFilling fill_holes(SurfaceMesh& mesh, size_t max_edges) {
  HoleFilling result;
  std::vector<SurfaceMesh::Halfedge_index> holes;  // one border half-edge per cycle
  PMP::extract_boundary_cycles(mesh, std::back_inserter(holes));
  for (const SurfaceMesh::Halfedge_index hole : holes) {
    // A patch filled before may have closed this cycle too (a border that
    // touches itself is one cycle here, walked through its pinch).
    if (!mesh.is_border(hole)) continue;
    size_t edges = 0;
    std::vector<repair::Point> corners;
    for (auto h = hole; edges == 0 || h != hole; h = mesh.next(h)) ++edges, corners.push_back(mesh.point(mesh.target(h)));
    std::sort(corners.begin(), corners.end());
    if (std::adjacent_find(corners.begin(), corners.end()) != corners.end()) {
      // It passes twice through one point (two copies of it, split where
      // faces met at that point alone): a patch over it would meet itself there.
      result.touching.push_back(edges);
      continue;
    }
    if (edges > max_edges) {
      result.too_large.push_back(edges);
      continue;
    }
    std::vector<SurfaceMesh::Face_index> patch;
    std::vector<SurfaceMesh::Vertex_index> added;
    const bool faired =
        std::get<0>(PMP::triangulate_refine_and_fair_hole(mesh, hole, std::back_inserter(patch), std::back_inserter(added),
                                                          CGAL::parameters::use_delaunay_triangulation(true)));
    if (patch.empty()) {
      result.failed.push_back(edges);
      continue;
    }
    ++result.filled;
    result.triangles_added += patch.size();
    result.faired_roughly += !faired;
  }
  return result;
}

}  // namespace umbra
