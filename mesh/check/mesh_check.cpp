#include "mesh/check/mesh_check.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/task_group.h>

#include "mesh/check/components.hpp"
#include "mesh/check/edge_groups.hpp"
#include "mesh/check/face_classes.hpp"
#include "mesh/check/face_flips.hpp"
#include "mesh/check/point_merging.hpp"
#include "mesh/check/polygon_triangulation.hpp"
#include "mesh/check/revisiting_polygons.hpp"
#include "mesh/check/self_intersections.hpp"
#include "mesh/check/solid_orientation.hpp"
#include "mesh/input_error.hpp"

namespace umbra {
namespace {

template <typename List>
bool room_for(const List& list, size_t most) {
  return list.size() < most;
}

// Where a face is: the mean of its distinct corners' positions.
glm::dvec3 mean_of_distinct(std::vector<uint32_t> corners, const std::vector<glm::dvec3>& positions) {
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  glm::dvec3 sum(0.0);
  for (const uint32_t v : corners) sum += positions[v];
  return corners.empty() ? sum : sum / double(corners.size());
}

// Per component, from what the stages found: closed, manifold, orientable
// and genus.
void summarise_components(const ComponentLabels& labels, MeshReport& report) {
  for (size_t i = 0; i < report.components.size(); ++i) {
    ComponentReport& c = report.components[i];
    c.euler_characteristic = int64_t(c.vertices) - int64_t(c.edges) + int64_t(c.faces);
    c.manifold = c.non_manifold_edges == 0 && c.non_manifold_vertices == 0;
    c.closed = is_closed_2_manifold(c.shape());
    c.orientable = !labels.conflict[i];
    c.consistently_oriented = c.orientable && labels.inconsistent[i] == 0;
    if (c.manifold && c.orientable) c.genus = (2 - c.euler_characteristic - int64_t(c.border_loops)) / 2;
    if (!c.orientable) ++report.non_orientable_components;
  }
}

// Which way each closed, orientable component faces (facing_of_closed_components),
// where the search for self-intersections says which cross a face: with no
// complete search, none is known not to. And which hide their back faces: a
// shell that crosses none of its own faces has winding number 0 or +-1
// round every point, by the sign of its volume.
void decide_facing(const std::vector<glm::dvec3>& positions, const FaceTriangles& triangles, const std::vector<uint8_t>& flipped,
                   const std::vector<uint32_t>& component_of_triangle, const std::vector<uint32_t>& component_of_face,
                   const SelfIntersections* found, MeshReport& report) {
  std::vector<ComponentReport>& comps = report.components;
  const bool known = found && found->complete;
  std::vector<uint8_t> shells(comps.size(), 0), tangled(comps.size(), known ? 0 : 1), crosses_itself(comps.size(), known ? 0 : 1);
  for (size_t i = 0; i < comps.size(); ++i) shells[i] = comps[i].closed && comps[i].orientable;
  if (known)
    for (const auto& [f, g] : found->pairs) {
      const uint32_t a = component_of_face[f], b = component_of_face[g];
      tangled[a] = tangled[b] = 1;
      if (a == b) crosses_itself[a] = 1;
    }
  const ShellFacing shell_facing = facing_of_closed_components(positions, triangles.triangles, component_of_triangle,
                                                               comps.size(), shells, tangled, &flipped);
  for (size_t i = 0; i < comps.size(); ++i) {
    if (!shells[i]) continue;
    comps[i].enclosed_volume = shell_facing.volume[i];
    report.enclosed_volume = report.enclosed_volume.value_or(0.0) + shell_facing.volume[i];
    const Facing facing = shell_facing.facing[i];
    const bool turned = facing == Facing::kWrong;  // the renderer turns it round
    comps[i].hides_back_faces = !crosses_itself[i] && (shell_facing.volume[i] > 0.0) != turned;
    if (facing == Facing::kUndecided) {
      ++report.undecided_components;
      continue;
    }
    comps[i].outward = !turned;
    if (turned) ++report.inward_components;
  }
}

// Per component, the triangle edges with more than two faces that are no
// non-manifold edge of its polygons: diagonals along another edge.
void count_overlapping_diagonals(const EdgeTable& edges, const std::vector<uint32_t>& component_of_triangle, MeshReport& report) {
  std::vector<uint32_t> touched;
  for (size_t e = 0; e < edges.size(); ++e) {
    const uint32_t count = edges.use_count(e);
    if (count <= 2) continue;
    touched.clear();
    for (uint32_t k = 0; k < count; ++k) touched.push_back(component_of_triangle[EdgeTable::face_of(edges.uses[edges.first_use[e] + k])]);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (const uint32_t component : touched) ++report.components[component].overlapping_diagonals;
  }
  for (ComponentReport& c : report.components) c.overlapping_diagonals -= std::min(c.overlapping_diagonals, c.non_manifold_edges);
}

// The stages in order, each a function of what the ones before it found
// (face_classes, edge_groups, components, face_flips), and the report made
// from their values. With `disposable` (the soup itself), its points are
// freed once merged and its corners become the merged vertices' in place.
MeshAnalysis analyse(const PolygonSoup& soup, PolygonSoup* disposable, const CheckOptions& options) {
  if (soup.corners.size() >= (size_t(1) << 31))
    throw InputError({soup.path, 0, 0}, "too large to check: more than 2^31 face corners");
  if (has_revisiting_polygons(soup)) {
    // Faces are counted and numbered as split (the warning says how).
    PolygonSoup split = split_revisiting_polygons(soup);
    return analyse(split, &split, options);
  }
  MeshAnalysis analysis;
  MeshReport& report = analysis.report;
  MeshReport::Examples& examples = report.examples;
  report.path = soup.path;
  report.format = soup.format;
  report.warnings = soup.warnings;
  report.file_vertices = soup.points.size();
  report.file_faces = soup.polygon_count();
  if (!soup.points.empty()) {
    report.bbox_min = report.bbox_max = soup.points[0];
    for (const glm::dvec3& p : soup.points) {
      report.bbox_min = glm::min(report.bbox_min, p);
      report.bbox_max = glm::max(report.bbox_max, p);
    }
  }

  MergedPoints merged = merge_coincident_points(soup.points);
  const size_t vertex_count = merged.positions.size();
  report.merged_vertices = soup.points.size() - vertex_count;
  if (disposable) std::vector<glm::dvec3>().swap(disposable->points);
  const auto vertex_ref = [&](uint32_t v) {
    return ElementRef{merged.first_point[v], soup.point_line(merged.first_point[v]), merged.positions[v]};
  };
  // Colours belong to the file's corners: kept, with each corner's merged
  // vertex, to find each triangle's once the triangles are final.
  const bool coloured = !soup.point_colors.empty() && soup.point_colors.size() == report.file_vertices;  // the points may be freed by now
  const bool textured = !soup.corner_uvs.empty() && soup.corner_uvs.size() == soup.corners.size();
  const bool normals = !soup.corner_normals.empty() && soup.corner_normals.size() == soup.corners.size();
  std::vector<glm::vec3> corner_colors;
  if (coloured) {
    corner_colors.resize(soup.corners.size());
    for (size_t c = 0; c < soup.corners.size(); ++c) corner_colors[c] = soup.point_colors[soup.corners[c]];
  }
  std::vector<uint32_t> corners;
  if (disposable) {
    for (uint32_t& corner : disposable->corners) corner = merged.vertex_of_point[corner];
    corners = std::move(disposable->corners);
  } else {
    corners.resize(soup.corners.size());
    for (size_t c = 0; c < soup.corners.size(); ++c) corners[c] = merged.vertex_of_point[soup.corners[c]];
  }
  std::vector<uint32_t>().swap(merged.vertex_of_point);
  const std::vector<uint32_t> merged_corners = coloured || textured || normals ? corners : std::vector<uint32_t>();

  // The topological stages; what only they need is freed at the end of the block.
  FaceTriangles triangles;
  ComponentLabels labels;
  std::vector<uint8_t> flip;
  // The self-intersection search needs only the triangles: it runs beside the
  // topological stages, and they are turned round only once it is done. What
  // it uses is declared before it, so that it outlives the search should a
  // stage throw.
  SelfIntersections found;
  const bool for_culling = options.self_intersection_seconds <= 0.0 && options.decide_back_faces;
  bool searched = options.self_intersection_seconds > 0.0;
  tbb::task_group search;
  std::optional<EdgeTable> face_edges;  // for the triangles' topology, when asked and all faces are triangles
  bool has_polygons = false;            // faces in the topology with more than three corners
  {
    const FaceClasses faces = classify_file_faces(soup, std::move(corners), merged.positions);
    const auto face_ref = [&](uint32_t f) {
      const auto first = faces.corners.begin() + soup.polygon_starts[f], last = faces.corners.begin() + soup.polygon_starts[f + 1];
      return ElementRef{f, soup.polygon_line(f), mean_of_distinct({first, last}, merged.positions)};
    };
    triangles = triangulate_faces(soup, faces, merged.positions);
    if (searched)
      search.run([&] {
        found = find_self_intersections(merged.positions, triangles.triangles, triangles.face,
                                        options.self_intersection_seconds, options.max_examples);
      });
    std::vector<uint8_t> used(vertex_count, 0);
    for (const uint32_t v : faces.corners) used[v] = 1;
    report.vertices = size_t(std::count(used.begin(), used.end(), 1));
    report.isolated_vertices = vertex_count - report.vertices;
    for (uint32_t f = 0; f < soup.polygon_count(); ++f) {
      if (!faces.degenerate(f)) continue;
      ++report.degenerate_faces;
      if (room_for(examples.degenerate_faces, options.max_examples)) examples.degenerate_faces.push_back(face_ref(f));
    }
    for (uint32_t f = 0; f < soup.polygon_count(); ++f) {
      if (!faces.duplicate[f]) continue;
      ++report.duplicate_faces;
      if (room_for(examples.duplicate_faces, options.max_examples)) examples.duplicate_faces.push_back({face_ref(f), face_ref(faces.duplicate_of[f])});
    }

    for (uint32_t f = 0; f < soup.polygon_count() && !has_polygons; ++f)
      has_polygons = faces.in_topology(f) && soup.corner_count(f) > 3;
    if (options.triangle_topology && !has_polygons) face_edges.emplace();
    EdgeGroups groups = group_edges(soup, faces, vertex_count, face_edges ? &*face_edges : nullptr);
    report.edges = groups.edges.size();
    report.inconsistent_edges = groups.inconsistent_edge_faces.size();
    for (const EdgeRun& e : groups.edges) {
      if (e.uses == 1) {
        ++report.border_edges;
        if (room_for(examples.border_edges, options.max_examples)) examples.border_edges.push_back({vertex_ref(e.a), vertex_ref(e.b)});
      } else if (e.uses > 2) {
        ++report.non_manifold_edges;
        if (room_for(examples.non_manifold_edges, options.max_examples)) examples.non_manifold_edges.push_back({vertex_ref(e.a), vertex_ref(e.b)});
      }
    }

    labels = label_components(faces, groups);
    ComponentVertices fans = find_vertex_fans(soup, faces, groups, labels, vertex_count);
    report.non_manifold_vertices = fans.non_manifold_vertices.size();
    for (size_t k = 0; k < std::min(fans.non_manifold_vertices.size(), options.max_examples); ++k)
      examples.non_manifold_vertices.push_back(vertex_ref(fans.non_manifold_vertices[k]));
    const BorderLoops loops = count_border_loops(groups, labels, vertex_count);
    report.border_loops = loops.loops;
    for (size_t i = 0; i < labels.reports.size(); ++i) {
      labels.reports[i].vertices = fans.vertices[i];
      labels.reports[i].border_loops = loops.per_component[i];
      labels.reports[i].non_manifold_vertices = fans.pinched_vertices[i];
    }

    flip = faces_to_flip(faces, groups.flips, labels.of_face, labels.conflict);
    for (uint32_t f = 0; f < soup.polygon_count(); ++f) {
      if (!flip[f]) continue;
      ++report.faces_to_flip;
      if (room_for(examples.faces_to_flip, options.max_examples)) examples.faces_to_flip.push_back(face_ref(f));
    }

    // V - E + F over the faces in the topology, each vertex once.
    size_t topology_faces = 0;
    for (const ComponentReport& c : labels.reports) topology_faces += c.faces;
    report.euler_characteristic = int64_t(fans.topology_vertices) - int64_t(groups.edges.size()) + int64_t(topology_faces);
  }
  report.components = labels.reports;
  report.triangles = triangles.triangles.size();
  for (const auto& [a, b, c] : triangles.triangles)
    report.area += 0.5 * glm::length(glm::cross(merged.positions[b] - merged.positions[a], merged.positions[c] - merged.positions[a]));
  std::vector<uint32_t> component_of_triangle(triangles.triangles.size());
  for (size_t t = 0; t < triangles.triangles.size(); ++t) component_of_triangle[t] = labels.of_face[triangles.face[t]];
  summarise_components(labels, report);
  search.wait();
  // The flips are read, not yet made.
  std::vector<uint8_t> flipped(triangles.triangles.size());
  for (size_t t = 0; t < triangles.triangles.size(); ++t) flipped[t] = flip[triangles.face[t]];
  const auto decide = [&](const SelfIntersections* search_found) {
    decide_facing(merged.positions, triangles, flipped, component_of_triangle, labels.of_face, search_found, report);
  };
  // Only a mesh whose every component is closed can have its back faces
  // culled (BackFaces). Where each would face out as loaded, none turned and
  // none nested, were no shell to cross itself, the picture asks the one
  // question left (kHiddenUnlessSeen) at the cost of drawing the back faces
  // once: no search. Else a search decides the facing, as the check's does.
  const bool all_closed = !report.components.empty() &&
                          std::all_of(report.components.begin(), report.components.end(),
                                      [](const ComponentReport& c) { return c.closed && c.orientable; });
  if (for_culling && all_closed) {
    const MeshReport before = report;
    SelfIntersections none;  // as a complete search that found nothing would say
    decide(&none);
    if (report.back_faces_hidden() && report.inward_components == 0) {
      analysis.back_faces = BackFaces::kHiddenUnlessSeen;
      // Unknown without a search (the facings stand as they would without crossings).
      for (ComponentReport& c : report.components) c.hides_back_faces = false;
    } else {
      report = before;
      found = find_self_intersections(merged.positions, triangles.triangles, triangles.face,
                                      std::numeric_limits<double>::infinity(), options.max_examples);
      searched = true;
      decide(&found);
      if (report.back_faces_hidden()) analysis.back_faces = BackFaces::kHidden;
    }
  } else {
    decide(searched ? &found : nullptr);
  }
  turn_flipped(triangles, flip);
  // The renderer gets closed components facing outward, so that it can cull
  // their back faces (the file's orientation stays in the report).
  const auto faces_in = [&](size_t t) { return report.components[component_of_triangle[t]].outward == false; };
  for (size_t t = 0; t < triangles.triangles.size(); ++t)
    if (faces_in(t)) std::swap(triangles.triangles[t][1], triangles.triangles[t][2]);
  // A mesh with polygons: its triangles' own edges, whose diagonals may run
  // along other edges.
  std::optional<EdgeTable> triangle_edges;
  if (has_polygons) {
    triangle_edges = build_edge_table(triangles.triangles, merged.positions.size());
    count_overlapping_diagonals(*triangle_edges, component_of_triangle, report);
  }
  if (options.triangle_topology) {
    EdgeTable edges;
    if (triangle_edges) {
      edges = std::move(*triangle_edges);
    } else {
      std::vector<uint8_t> turned = std::move(flipped);  // flipped, then turned outward
      for (size_t t = 0; t < turned.size(); ++t) turned[t] ^= uint8_t(faces_in(t));
      edges = triangle_edges_from_face_edges(std::move(*face_edges), triangles.face, turned);
    }
    SilhouetteComponents components = closed_components_of(edges, component_of_triangle, report);
    analysis.topology = TriangleTopology{std::move(edges), std::move(components)};
  }

  report.self_intersections.time_limit_seconds = options.self_intersection_seconds;
  if (searched) {
    report.self_intersections.checked = true;
    report.self_intersections.complete = found.complete;
    report.self_intersections.face_pairs = found.face_pairs;
    report.self_intersections.seconds = found.seconds;
    // The faces' corners are gone by now: each crossing face's from its triangles.
    std::unordered_map<uint32_t, std::vector<uint32_t>> corners_of;
    for (const auto& [f, g] : found.examples) corners_of[f], corners_of[g];
    for (size_t t = 0; t < triangles.triangles.size(); ++t)
      if (const auto it = corners_of.find(triangles.face[t]); it != corners_of.end())
        it->second.insert(it->second.end(), triangles.triangles[t].begin(), triangles.triangles[t].end());
    const auto crossing_ref = [&](uint32_t f) {
      return ElementRef{f, soup.polygon_line(f), mean_of_distinct(corners_of[f], merged.positions)};
    };
    for (const auto& [f, g] : found.examples) examples.self_intersections.push_back({crossing_ref(f), crossing_ref(g)});
  }
  analysis.positions = std::move(merged.positions);
  analysis.triangles = std::move(triangles.triangles);
  analysis.triangle_face = std::move(triangles.face);
  if (coloured) analysis.triangle_colors.resize(analysis.triangles.size());
  if (textured) analysis.triangle_uvs.resize(analysis.triangles.size());
  if (normals) analysis.triangle_normals.resize(analysis.triangles.size());
  if (coloured || textured || normals) {
    // Each triangle corner's file corner: the first of its face's at that vertex.
    for (size_t t = 0; t < analysis.triangles.size(); ++t) {
      const uint32_t f = analysis.triangle_face[t];
      for (size_t k = 0; k < 3; ++k)
        for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c)
          if (merged_corners[c] == analysis.triangles[t][k]) {
            if (coloured) analysis.triangle_colors[t][k] = corner_colors[c];
            if (textured) analysis.triangle_uvs[t][k] = soup.corner_uvs[c];
            if (normals) analysis.triangle_normals[t][k] = soup.corner_normals[c];
            break;
          }
    }
  }
  if (!soup.polygon_materials.empty()) {
    analysis.materials = soup.materials;
    analysis.triangle_materials.reserve(analysis.triangle_face.size());
    for (uint32_t f : analysis.triangle_face) analysis.triangle_materials.push_back(soup.polygon_material(f));
  }
  return analysis;
}

}  // namespace

MeshAnalysis analyse_mesh(const PolygonSoup& soup, const CheckOptions& options) { return analyse(soup, nullptr, options); }
MeshAnalysis analyse_mesh(PolygonSoup&& soup, const CheckOptions& options) { return analyse(soup, &soup, options); }
MeshReport check_mesh(const PolygonSoup& soup, const CheckOptions& options) { return analyse_mesh(soup, options).report; }
MeshReport check_mesh(PolygonSoup&& soup, const CheckOptions& options) { return analyse_mesh(std::move(soup), options).report; }

}  // namespace umbra
