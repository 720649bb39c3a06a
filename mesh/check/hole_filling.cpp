#include "mesh/check/hole_filling.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/Euler_operations.h>

namespace umbra {

namespace PMP = CGAL::Polygon_mesh_processing;
using repair::Point;
using repair::SurfaceMesh;

namespace {

// A border loop's points, in its order, cut where it comes back to a point
// it passed: each piece between two visits is a lobe, a loop of its own.
std::vector<std::vector<Point>> lobes_of(const std::vector<Point>& loop) {
  std::vector<std::vector<Point>> lobes;
  std::vector<Point> open;
  for (const Point& p : loop) {
    const auto again = std::find(open.begin(), open.end(), p);
    if (again != open.end()) {
      lobes.emplace_back(again, open.end());
      open.erase(again + 1, open.end());
    } else {
      open.push_back(p);
    }
  }
  lobes.push_back(open);
  lobes.erase(std::remove_if(lobes.begin(), lobes.end(), [](const std::vector<Point>& lobe) { return lobe.size() < 3; }),
              lobes.end());
  return lobes;
}

// The triangles of a lobe's least-area triangulation, in the lobe's
// orientation; none where none is found.
std::vector<std::array<Point, 3>> triangulated_lobe(const std::vector<Point>& lobe) {
  std::vector<CGAL::Triple<int, int, int>> triangles;
  PMP::triangulate_hole_polyline(lobe, std::back_inserter(triangles), CGAL::parameters::use_delaunay_triangulation(true));
  std::vector<std::array<Point, 3>> out;
  for (const auto& t : triangles) out.push_back({lobe[size_t(t.first)], lobe[size_t(t.second)], lobe[size_t(t.third)]});
  return out;
}

// Per face, whether its connected component is flat: a panel, a sheet, a
// lone triangle. Flat is most of its area facing one way (the faces' summed
// normal at least half their summed area) and every point within 1e-7 of
// the part's size from the plane through one of them: a flat part written
// in single precision is flat to about that.
std::vector<uint8_t> faces_on_flat_parts(SurfaceMesh& mesh) {
  auto component = mesh.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:flat_component", 0).first;
  struct Part {
    CGAL::Vector_3<repair::Kernel> normal{0, 0, 0};
    double area = 0.0;
    CGAL::Bbox_3 box;
    Point on;  // one of its points
    bool flat = true;
    double length = 0.0, size = 0.0;  // of its normal, of its box's diagonal
  };
  std::vector<Part> parts(PMP::connected_components(mesh, component));
  for (const auto f : mesh.faces()) {
    Part& part = parts[component[f]];
    const auto h = mesh.halfedge(f);
    const Point &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)), &c = mesh.point(mesh.target(mesh.next(h)));
    const auto n = CGAL::cross_product(b - a, c - a);
    part.normal = part.normal + n;
    part.area += std::sqrt(n.squared_length());
    part.box += a.bbox() + b.bbox() + c.bbox();
    part.on = a;
  }
  for (Part& part : parts) {
    part.length = std::sqrt(part.normal.squared_length());
    part.flat = part.area > 0.0 && part.length >= 0.5 * part.area;
    const CGAL::Bbox_3& box = part.box;
    part.size = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
  }
  for (const auto f : mesh.faces()) {
    Part& part = parts[component[f]];
    if (!part.flat) continue;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      part.flat = part.flat && std::abs(CGAL::scalar_product(mesh.point(v) - part.on, part.normal)) / part.length <= 1e-7 * part.size;
  }
  std::vector<uint8_t> flat(mesh.num_faces(), 0);
  for (const auto f : mesh.faces()) flat[f.idx()] = parts[component[f]].flat;
  mesh.remove_property_map(component);
  return flat;
}

}  // namespace

// Whether a face of `patch` crosses a face of the part it closes (`part`,
// by `part_of` each face the mesh had before the filling; a patch's own
// faces count as the part's), decided with CGAL's exact predicates among the
// faces whose boxes meet the patch's: a fill that passes through the
// surface round it (a fold's) is no repair. Crossings the mesh had before
// are not the patch's, and nor are crossings with other parts (a spider's
// legs through its body), which the repair's union resolves later.
bool patch_crosses_mesh(const SurfaceMesh& mesh, const std::vector<SurfaceMesh::Face_index>& patch,
                        const std::vector<std::size_t>& part_of, std::size_t part) {
  const auto box_of = [&](SurfaceMesh::Face_index f) {
    CGAL::Bbox_3 box;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) box += mesh.point(v).bbox();
    return box;
  };
  CGAL::Bbox_3 around;
  for (const auto f : patch) around += box_of(f);
  std::vector<SurfaceMesh::Face_index> near;
  for (const auto f : mesh.faces())
    if (CGAL::do_overlap(box_of(f), around)) near.push_back(f);
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> crossing;
  PMP::self_intersections(near, mesh, std::back_inserter(crossing));
  const std::set<SurfaceMesh::Face_index> in_patch(patch.begin(), patch.end());
  const auto in_part = [&](SurfaceMesh::Face_index f) { return f.idx() >= part_of.size() || part_of[f.idx()] == part; };
  return std::any_of(crossing.begin(), crossing.end(), [&](const auto& pair) {
    return (in_patch.count(pair.first) && in_part(pair.second)) || (in_patch.count(pair.second) && in_part(pair.first));
  });
}

// Takes `patch` out of `mesh` again, leaving its hole as it was (the added
// points go with the faces; the border's half-edges stay).
void remove_patch(SurfaceMesh& mesh, const std::vector<SurfaceMesh::Face_index>& patch) {
  for (const auto f : patch) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
}

HoleFilling fill_holes(SurfaceMesh& mesh, size_t max_edges, std::vector<std::array<Point, 3>>& lobe_triangles,
                       bool refuse_crossing_patches) {
  HoleFilling result;
  std::vector<SurfaceMesh::Halfedge_index> holes;  // one border half-edge per cycle
  PMP::extract_boundary_cycles(mesh, std::back_inserter(holes));
  const std::vector<uint8_t> flat = faces_on_flat_parts(mesh);
  bool removed = false;  // a patch taken out again: its elements are collected at the end
  // Each face's part (connected component) before the filling.
  std::vector<std::size_t> part_of(mesh.number_of_faces() + mesh.number_of_removed_faces());
  if (refuse_crossing_patches) {
    auto parts = mesh.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:umbra_part", 0).first;
    PMP::connected_components(mesh, parts);
    for (const auto f : mesh.faces()) part_of[f.idx()] = parts[f];
    mesh.remove_property_map(parts);
  }
  for (const SurfaceMesh::Halfedge_index hole : holes) {
    // A patch filled before may have closed this cycle too (a border that
    // touches itself is one cycle here, walked through its pinch).
    if (!mesh.is_border(hole)) continue;
    // A flat part has no inside: filling its outline would lay a second
    // copy of it back to back, closed round nothing.
    if (const auto f = mesh.face(mesh.opposite(hole)); f.idx() < flat.size() && flat[f.idx()]) {
      ++result.on_flat_parts;
      continue;
    }
    size_t edges = 0;
    std::vector<Point> loop;
    for (auto h = hole; edges == 0 || h != hole; h = mesh.next(h)) ++edges, loop.push_back(mesh.point(mesh.source(h)));
    if (edges > max_edges) {
      result.too_large.push_back(edges);
      continue;
    }
    std::vector<Point> distinct = loop;
    std::sort(distinct.begin(), distinct.end());
    if (std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end()) {
      // A patch over the whole loop would meet itself at the point it
      // passes twice: each lobe is filled on its own instead.
      std::vector<std::array<Point, 3>> triangles;
      const std::vector<std::vector<Point>> lobes = lobes_of(loop);
      for (const std::vector<Point>& lobe : lobes) {
        const std::vector<std::array<Point, 3>> filled = triangulated_lobe(lobe);
        if (filled.empty()) {
          triangles.clear();
          break;
        }
        triangles.insert(triangles.end(), filled.begin(), filled.end());
      }
      if (triangles.empty()) {
        result.failed.push_back(edges);
        continue;
      }
      ++result.filled;
      result.lobes += lobes.size();
      lobe_triangles.insert(lobe_triangles.end(), triangles.begin(), triangles.end());
      continue;
    }
    std::vector<SurfaceMesh::Face_index> patch;
    std::vector<SurfaceMesh::Vertex_index> added;
    bool faired =
        std::get<0>(PMP::triangulate_refine_and_fair_hole(mesh, hole, std::back_inserter(patch), std::back_inserter(added),
                                                          CGAL::parameters::use_delaunay_triangulation(true)));
    if (patch.empty()) {
      result.failed.push_back(edges);
      continue;
    }
    const std::size_t part = part_of[mesh.face(mesh.opposite(hole)).idx()];
    if (refuse_crossing_patches && patch_crosses_mesh(mesh, patch, part_of, part)) {
      // Faired, the patch bent through the surface: the least-area
      // triangulation of the border alone, flat; else the hole stays open.
      remove_patch(mesh, patch);
      removed = true;
      patch.clear();
      PMP::triangulate_hole(mesh, hole, std::back_inserter(patch), CGAL::parameters::use_delaunay_triangulation(true));
      if (!patch.empty() && patch_crosses_mesh(mesh, patch, part_of, part)) remove_patch(mesh, patch), patch.clear();
      if (patch.empty()) {
        ++result.crossing;
        continue;
      }
      ++result.filled_flat;
      faired = true;  // not asked of this patch
    }
    ++result.filled;
    result.triangles_added += patch.size();
    result.faired_roughly += !faired;
  }
  if (removed) mesh.collect_garbage();
  return result;
}

size_t add_lobe_patches(SurfaceMesh& mesh, const std::vector<std::array<Point, 3>>& triangles) {
  if (triangles.empty()) return 0;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  PMP::polygon_mesh_to_polygon_soup(mesh, points, polygons);
  const size_t first = polygons.size();
  for (const auto& t : triangles) {
    polygons.push_back({points.size(), points.size() + 1, points.size() + 2});
    points.insert(points.end(), t.begin(), t.end());
  }
  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);  // splits again the points whose fans stay apart
  SurfaceMesh rebuilt;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, rebuilt);  // faces in the soup's order
  mesh = std::move(rebuilt);
  std::vector<SurfaceMesh::Face_index> patch;
  for (size_t f = first; f < mesh.number_of_faces(); ++f) patch.push_back(SurfaceMesh::Face_index(SurfaceMesh::size_type(f)));
  std::vector<SurfaceMesh::Face_index> refined;
  std::vector<SurfaceMesh::Vertex_index> added;
  PMP::refine(mesh, patch, std::back_inserter(refined), std::back_inserter(added));
  PMP::fair(mesh, added);
  return patch.size() + refined.size();
}

}  // namespace umbra
