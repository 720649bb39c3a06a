#include "mesh/check/mesh_repair.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <limits>
#include <map>
#include <optional>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/internal/Snapping/snap.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include "mesh/check/hole_filling.hpp"
#include "mesh/check/point_merging.hpp"
#include "mesh/check/repair_attributes.hpp"
#include "mesh/check/revisiting_polygons.hpp"
#include "mesh/check/self_intersection_removal.hpp"
#include "mesh/check/repair_mesh_type.hpp"
#include "mesh/check/self_intersections.hpp"
#include "mesh/check/solid_orientation.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_format.hpp"
#include "mesh/word_list.hpp"

namespace umbra {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using repair::Point;
using Mesh = repair::SurfaceMesh;
using Polygon = std::vector<std::size_t>;

std::string counted(size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

// Drops repeated corners next to each other (after merging, "a b b c" is the
// triangle "a b c"), then every polygon left with fewer than 3 distinct
// corners. Returns how many polygons were dropped.
size_t remove_degenerate_polygons(std::vector<Polygon>& polygons) {
  const size_t before = polygons.size();
  std::vector<Polygon> kept;
  kept.reserve(polygons.size());
  for (Polygon& polygon : polygons) {
    Polygon simple;
    for (size_t k = 0; k < polygon.size(); ++k)
      if (polygon[k] != polygon[(k + 1) % polygon.size()]) simple.push_back(polygon[k]);
    Polygon distinct = simple;
    std::sort(distinct.begin(), distinct.end());
    const bool repeats = std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end();
    if (simple.size() >= 3 && !repeats) kept.push_back(std::move(simple));
  }
  polygons = std::move(kept);
  return before - polygons.size();
}

// What orient_closed_components_outward did and found.
struct Outward {
  size_t reversed = 0;             // closed components turned
  std::vector<FacePair> crossing;  // pairs of faces that cross
};

// Reverses every closed component that faces into the solid it bounds
// (facing_of_closed_components, with the self-intersection search saying
// which cross a face: those, and those inside them, stay as they are).
Outward orient_closed_components_outward(Mesh& mesh) {
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  const std::size_t count = PMP::connected_components(mesh, component);
  std::vector<std::vector<Mesh::Face_index>> faces(count);
  std::vector<uint8_t> closed(count, 1);
  std::vector<glm::dvec3> positions(mesh.number_of_vertices());
  for (const Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    positions[size_t(v)] = {p.x(), p.y(), p.z()};
  }
  std::vector<std::array<uint32_t, 3>> triangles;  // each face as a fan, for the volumes
  std::vector<uint32_t> component_of, face_of;
  std::vector<Mesh::Face_index> mesh_face_of;  // per triangle
  for (const Mesh::Face_index f : mesh.faces()) {
    faces[component[f]].push_back(f);
    std::vector<uint32_t> corners;
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      if (mesh.is_border(mesh.opposite(h))) closed[component[f]] = 0;
      corners.push_back(uint32_t(mesh.source(h)));
    }
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      triangles.push_back({corners[0], corners[k], corners[k + 1]});
      component_of.push_back(uint32_t(component[f]));
      face_of.push_back(uint32_t(triangles.size() - 1));  // each triangle on its own: fans cross nothing
      mesh_face_of.push_back(f);
    }
  }
  const SelfIntersections found = find_self_intersections(positions, triangles, face_of,
                                                          std::numeric_limits<double>::infinity(), 0);
  std::vector<uint8_t> tangled(count, 0);
  for (const auto& [s, t] : found.pairs) tangled[component_of[s]] = tangled[component_of[t]] = 1;
  const std::vector<Facing> facing = facing_of_closed_components(positions, triangles, component_of, count, closed, tangled).facing;
  size_t reversed = 0;
  for (std::size_t c = 0; c < count; ++c) {
    if (facing[c] != Facing::kWrong) continue;
    PMP::reverse_face_orientations(faces[c], mesh);
    ++reversed;
  }
  mesh.remove_property_map(component);
  Outward outward{reversed, {}};
  for (const auto& [s, t] : found.pairs) outward.crossing.emplace_back(mesh_face_of[s], mesh_face_of[t]);
  return outward;
}

// Fills the holes of `mesh` (a triangle mesh) of at most `max_hole_edges`
// edges, those that pass twice through a point lobe by lobe.
HoleFilling filled(Mesh& mesh, size_t max_hole_edges, bool refuse_crossing_patches) {
  std::vector<std::array<Point, 3>> lobe_triangles;
  HoleFilling holes = fill_holes(mesh, max_hole_edges, lobe_triangles, refuse_crossing_patches);
  holes.triangles_added += add_lobe_patches(mesh, lobe_triangles);
  return holes;
}

// What fill_holes did, in a line each.
void say_holes(const HoleFilling& holes, size_t max_edges, std::vector<std::string>& changes) {
  if (holes.filled > 0) {
    std::string line = "filled " + counted(holes.filled, "hole", "holes") + " with " +
                       counted(holes.triangles_added, "triangle", "triangles") + ", refined and faired to the surface round them";
    if (holes.lobes)
      line += " (" + counted(holes.lobes, "lobe", "lobes") + " of holes whose border passes twice through a point, each filled on its own)";
    if (holes.faired_roughly)
      line += " (" + std::to_string(holes.faired_roughly) + " refined but not faired: the solver failed)";
    if (holes.filled_flat)
      line += " (" + std::to_string(holes.filled_flat) + " flat, by the border's least-area triangulation: faired, the patch crossed the mesh)";
    changes.push_back(line);
  }
  if (holes.crossing > 0)
    changes.push_back("left " + counted(holes.crossing, "hole", "holes") +
                      " open: every patch of it, faired or flat, crossed the mesh round it");
  if (!holes.too_large.empty()) {
    const size_t largest = *std::max_element(holes.too_large.begin(), holes.too_large.end());
    changes.push_back("left " + counted(holes.too_large.size(), "hole", "holes") + " of more than " + std::to_string(max_edges) +
                      " edges open (the largest has " + std::to_string(largest) + "; --max-hole-edges " + std::to_string(largest) +
                      " fills " + (holes.too_large.size() == 1 ? "it" : "them") + ")");
  }
  if (holes.on_flat_parts > 0)
    changes.push_back("left " + counted(holes.on_flat_parts, "hole", "holes") +
                      " of flat parts open: a flat part (a panel, a sheet) has no inside to close");
  if (!holes.failed.empty())
    changes.push_back("left " + counted(holes.failed.size(), "hole", "holes") +
                      " open that no triangulation without a degenerate or crossing triangle fills");
}

// Fills the holes of `mesh` (filled), where that leaves some trying again
// with its cracks snapped shut first, on a copy of `unfilled` (the mesh as
// it was, where it had holes); says what it did in `changes`.
void close_holes(Mesh& mesh, const std::optional<Mesh>& unfilled, size_t max_hole_edges, std::vector<std::string>& changes,
                 bool refuse_crossing_patches) {
  HoleFilling holes = filled(mesh, max_hole_edges, refuse_crossing_patches);
  if (unfilled && !CGAL::is_closed(mesh)) {
    // A crack between two patches whose points do not meet (as CAD
    // tessellations leave them) is a hole no patch fills well. Tried again
    // with the borders first snapped onto each other (CGAL's snap_borders:
    // each border point onto a point or edge across within a bound of its
    // own edges' lengths) and stitched, and kept only where that closes the
    // surface: snapping also moves points of a border that is a true hole,
    // and of nearly equal copies, which --merge-tolerance merges better.
    Mesh snapped = *unfilled;
    const size_t moved = PMP::experimental::snap_borders(snapped);
    const size_t stitched = PMP::stitch_borders(snapped);
    PMP::remove_degenerate_faces(snapped);
    snapped.collect_garbage();
    HoleFilling snapped_holes = filled(snapped, max_hole_edges, refuse_crossing_patches);
    if (moved > 0 && CGAL::is_closed(snapped)) {
      changes.push_back("snapped " + counted(moved, "border point", "border points") + " onto the border across a crack and stitched " +
                        counted(stitched, "pair of border edges", "pairs of border edges") +
                        " (CGAL's snap_borders), which closed the surface where filling alone left holes");
      mesh = std::move(snapped);
      holes = snapped_holes;
    }
  }
  say_holes(holes, max_hole_edges, changes);
}

// Turns each closed component outward where that is decided, then merges
// parts that overlap into their union (self_intersection_removal.hpp);
// says what it did in `changes`. Returns the pairs of triangles that still
// cross.
size_t turn_outward_and_merge_overlaps(Mesh& mesh, std::vector<std::string>& changes) {
  const Outward outward = orient_closed_components_outward(mesh);
  if (outward.reversed > 0) changes.push_back("turned " + counted(outward.reversed, "closed component", "closed components") + " outward");
  if (!outward.crossing.empty()) {
    // Triangles, as the repair cuts them: a check counts the file's faces,
    // so a crossing quad pair may be two or four pairs here.
    const std::string pairs = counted(outward.crossing.size(), "pair", "pairs") + " of triangles that cross";
    const SelfIntersectionRemoval removal = remove_self_intersections(mesh, outward.crossing);
    if (removal.removed) {
      changes.push_back("removed the " + pairs + ": the parts that overlapped are one surface, bounding their union (" +
                        counted(mesh.number_of_faces(), "triangle", "triangles") + " now)");
      if (const size_t n = orient_closed_components_outward(mesh).reversed)
        changes.push_back("turned " + counted(n, "closed component", "closed components") + " of it outward");
    } else {
      changes.push_back("left the " + pairs + ": " + removal.why_not);
      return outward.crossing.size();
    }
  }
  return 0;
}

// The power of two the repair's points are scaled by, where their largest
// coordinate is beyond what its arithmetic holds (squared and cubed in
// CGAL's constructions, areas and volumes: 1e77 lost faces as degenerate,
// 1e200 made a NaN volume and turned a part the wrong way), or so small that
// its squares underflow; 0 where they are not. A power of two scales every
// double exactly, and back.
int scale_exponent(const std::vector<glm::dvec3>& points) {
  double largest = 0.0;
  for (const glm::dvec3& p : points) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  if (!(largest > 0.0) || !std::isfinite(largest) || (largest < 0x1p64 && largest > 0x1p-64)) return 0;
  return std::ilogb(largest);
}

// The repair itself, as repair_mesh documents it: the repaired surface, its
// changes said in `changes`.
// `placed` is where it put each of the soup's points when a merge within a
// tolerance moved some; left empty when each stays where the soup has it.
Mesh repaired_surface(const PolygonSoup& soup, const RepairOptions& options, std::vector<std::string>& changes,
                      std::vector<glm::dvec3>& placed) {
  const size_t max_hole_edges = options.max_hole_edges;
  const int shift = scale_exponent(soup.points);
  const auto scaled = [&](const glm::dvec3& p) { return Point(std::ldexp(p.x, -shift), std::ldexp(p.y, -shift), std::ldexp(p.z, -shift)); };
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for (const glm::dvec3& p : soup.points) points.push_back(scaled(p));
  std::vector<Polygon> polygons(soup.polygon_count());
  for (size_t f = 0; f < polygons.size(); ++f) polygons[f].assign(soup.polygon(f), soup.polygon(f) + soup.corner_count(f));
  if (options.merge_tolerance > 0.0) {
    const MergedPoints near = merge_nearby_points(soup.points, options.merge_tolerance);
    const MergedPoints equal = merge_coincident_points(soup.points);
    std::ostringstream within;
    within << options.merge_tolerance;
    if (const size_t n = equal.positions.size() - near.positions.size())
      changes.push_back("merged " + counted(n, "vertex", "vertices") + " into another within " + within.str() +
                        " (--merge-tolerance)");
    points.clear();
    for (const glm::dvec3& p : near.positions) points.push_back(scaled(p));
    placed.resize(soup.points.size());
    for (size_t p = 0; p < placed.size(); ++p) placed[p] = near.positions[near.vertex_of_point[p]];
    for (Polygon& polygon : polygons)
      for (std::size_t& v : polygon) v = near.vertex_of_point[v];
  }

  if (const size_t n = PMP::merge_duplicate_points_in_polygon_soup(points, polygons))
    changes.push_back("merged " + counted(n, "repeated vertex", "repeated vertices"));
  if (const size_t n = remove_degenerate_polygons(polygons))
    changes.push_back("removed " + counted(n, "face with a repeated vertex", "faces with a repeated vertex"));
  if (const size_t n = PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons))
    changes.push_back("removed " + counted(n, "duplicate face", "duplicate faces"));
  if (const size_t n = PMP::remove_isolated_points_in_polygon_soup(points, polygons))
    changes.push_back("removed " + counted(n, "unused vertex", "unused vertices"));
  if (polygons.empty()) throw InputError({soup.path, 0, 0}, "nothing left to repair: the mesh has no valid face");

  const size_t points_before_orienting = points.size();
  const std::vector<Polygon> before_orienting = polygons;
  // Orients each piece consistently, splitting vertices and edges where the
  // soup is not a manifold (PMP's documented way to make any soup a mesh).
  const bool was_orientable_manifold = PMP::orient_polygon_soup(points, polygons);
  size_t flipped = 0;
  for (size_t f = 0; f < polygons.size(); ++f) flipped += polygons[f] != before_orienting[f];
  if (flipped > 0) changes.push_back("flipped " + counted(flipped, "face", "faces") + " to orient them consistently");
  if (!was_orientable_manifold)
    changes.push_back("split " + counted(points.size() - points_before_orienting, "vertex", "vertices") +
                      " into copies where faces meet only at a point or cannot agree on an orientation (the copies "
                      "keep their coordinates, so the check below still sees those points)");

  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const size_t faces_before = mesh.number_of_faces();
  PMP::triangulate_faces(mesh);
  if (mesh.number_of_faces() != faces_before)
    changes.push_back("triangulated " + counted(faces_before, "face", "faces") + " into " +
                      counted(mesh.number_of_faces(), "triangle", "triangles"));
  if (const size_t n = PMP::stitch_borders(mesh))
    changes.push_back("stitched " + counted(n, "pair of coinciding border edges", "pairs of coinciding border edges"));

  const size_t triangles_before = mesh.number_of_faces();
  const bool all_removed = PMP::remove_degenerate_faces(mesh);
  mesh.collect_garbage();
  if (mesh.number_of_faces() != triangles_before)
    changes.push_back("collapsed degenerate triangles (" + counted(triangles_before - mesh.number_of_faces(), "triangle", "triangles") +
                      " fewer)");
  if (!all_removed) changes.push_back("could not remove every degenerate triangle");
  // The holes filled and the overlapping parts merged; where triangles still
  // cross after that (a faired patch bent through a fold, which no union
  // resolves), again with each patch that crosses its part refused (filled
  // flat, or left open): a fill that crosses the mesh is no repair. The
  // result with fewer crossings is kept.
  std::optional<Mesh> unfilled;
  if (!CGAL::is_closed(mesh)) unfilled = mesh;
  std::vector<std::string> filling;
  close_holes(mesh, unfilled, max_hole_edges, filling, false);
  const size_t crossing = turn_outward_and_merge_overlaps(mesh, filling);
  if (crossing > 0 && unfilled) {
    std::vector<std::string> refusing;
    Mesh again = *unfilled;
    close_holes(again, unfilled, max_hole_edges, refusing, true);
    if (turn_outward_and_merge_overlaps(again, refusing) < crossing) mesh = std::move(again), filling = std::move(refusing);
  }
  changes.insert(changes.end(), filling.begin(), filling.end());
  if (mesh.number_of_faces() == 0) throw InputError({soup.path, 0, 0}, "nothing left after the repair: every face was degenerate");
  if (shift != 0)
    for (const auto v : mesh.vertices()) {
      const Point& p = mesh.point(v);
      mesh.point(v) = Point(std::ldexp(p.x(), shift), std::ldexp(p.y(), shift), std::ldexp(p.z(), shift));
    }
  return mesh;
}

// The repaired surface as triangles over its own points, numbered afresh
// (hole filling may leave removed vertices among the mesh's), with the
// soup's attributes (repair_attributes.hpp).
TriangleFile repaired_triangle_file(const PolygonSoup& file_soup, const RepairOptions& options, std::vector<std::string>& changes) {
  // A face that passes twice through a point (a keyhole round a hole) is
  // its triangles, as the check reads it, rather than dropped as degenerate.
  std::optional<PolygonSoup> split;
  if (has_revisiting_polygons(file_soup)) {
    split = split_revisiting_polygons(file_soup);
    const size_t faces = split->warnings.size() - file_soup.warnings.size();
    changes.push_back("split " + counted(faces, "face that passes", "faces that pass") + " more than once through a point into " +
                      counted(split->polygon_count() - file_soup.polygon_count() + faces, "triangle", "triangles"));
  }
  const PolygonSoup& soup = split ? *split : file_soup;
  std::vector<glm::dvec3> placed;
  const Mesh mesh = repaired_surface(soup, options, changes, placed);
  std::vector<glm::dvec3> points;
  std::vector<uint32_t> index(mesh.num_vertices());
  points.reserve(mesh.number_of_vertices());
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    index[v.idx()] = uint32_t(points.size());
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  std::vector<std::array<uint32_t, 3>> triangles;
  triangles.reserve(mesh.number_of_faces());
  for (const auto f : mesh.faces()) {
    std::array<uint32_t, 3> t{};
    size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[k++] = index[v.idx()];
    triangles.push_back(t);
  }
  std::vector<std::array<glm::dvec3, 3>> split_from;
  if (const auto property = mesh.property_map<Mesh::Face_index, SplitFrom>(kSplitFromProperty); property.second) {
    split_from.reserve(triangles.size());
    for (const auto f : mesh.faces()) {
      std::array<glm::dvec3, 3>& from = split_from.emplace_back();
      for (size_t k = 0; k < 3; ++k) from[k] = {property.first[f][k].x(), property.first[f][k].y(), property.first[f][k].z()};
    }
  }
  return with_soup_attributes(soup, placed.empty() ? soup.points : placed, std::move(points), std::move(triangles), split_from);
}

}  // namespace

bool repair_can_write(const std::string& path) {
  const MeshFormat* format = mesh_format_by_id(mesh_format_of(path));
  return format && format->write;
}

RepairSummary repair_mesh(const PolygonSoup& soup, const std::string& output, const std::string& write_to,
                          const RepairOptions& options) {
  RepairSummary summary;
  const MeshFormat* format = mesh_format_by_id(mesh_format_of(output));
  if (!format || !format->write)
    throw InputError({output, 0, 0}, "cannot write the repaired mesh: write one of " + mesh_format_extensions(true));
  const TriangleFile repaired = repaired_triangle_file(soup, options, summary.changes);
  WrittenMesh written = format->write(repaired, output, write_to);
  if (!written.dropped.empty())
    summary.changes.push_back("left out the " + word_list(written.dropped, "and") + ", which " + std::string(format->name) +
                              " cannot keep (OBJ keeps them all)");
  summary.companions = std::move(written.companions);
  return summary;
}

RepairedTriangles repair_to_triangles(const PolygonSoup& soup, const RepairOptions& options) {
  RepairedTriangles repaired;
  TriangleFile file = repaired_triangle_file(soup, options, repaired.summary.changes);
  repaired.points = std::move(file.points);
  repaired.triangles = std::move(file.triangles);
  return repaired;
}

}  // namespace umbra
