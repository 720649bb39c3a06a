#include "mesh/check/mesh_check.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include <glm/geometric.hpp>

#include "mesh/input_error.hpp"
#include "mesh/predicates/orientation.hpp"
#include "mesh/check/point_merging.hpp"
#include "mesh/check/polygon_triangulation.hpp"
#include "mesh/check/self_intersections.hpp"
#include "mesh/check/solid_orientation.hpp"
#include "mesh/topology/union_find.hpp"

namespace umbra {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// The soup with coincident points merged, and what each face is.
struct Faces {
  std::vector<uint32_t> corners;  // vertex (merged point) indices, face after face as in the soup
  std::vector<uint8_t> repeats_vertex, collinear, duplicate;
  std::vector<uint32_t> duplicate_of;  // for a duplicate, the earlier face it repeats
  bool in_topology(size_t f) const { return !repeats_vertex[f] && !duplicate[f]; }
};

bool has_repeated_vertex(const uint32_t* v, uint32_t n) {
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = i + 1; j < n; ++j)
      if (v[i] == v[j]) return true;
  return false;
}

bool all_collinear(const std::vector<glm::dvec3>& positions, const uint32_t* v, uint32_t n) {
  for (uint32_t k = 2; k < n; ++k)
    if (!collinear(positions[v[0]], positions[v[1]], positions[v[k]])) return false;
  return true;
}

// Marks every face whose vertex set equals an earlier face's. Equal sets
// have the same smallest vertex, so faces are bucketed by it (a counting
// sort, in file order within a bucket) and compared only within a bucket,
// which for most vertices holds two or three faces.
void find_duplicates(const PolygonSoup& soup, size_t vertex_count, Faces& faces) {
  const auto smallest = [&](uint32_t f) {
    const uint32_t* v = faces.corners.data() + soup.polygon_starts[f];
    return *std::min_element(v, v + soup.corner_count(f));
  };
  std::vector<uint32_t> bucket_start(vertex_count + 1, 0);
  for (uint32_t f = 0; f < soup.polygon_count(); ++f)
    if (!faces.repeats_vertex[f]) ++bucket_start[smallest(f) + 1];
  for (size_t v = 0; v < vertex_count; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<uint32_t> bucketed(bucket_start[vertex_count]);
  {
    std::vector<uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (uint32_t f = 0; f < soup.polygon_count(); ++f)
      if (!faces.repeats_vertex[f]) bucketed[fill[smallest(f)]++] = f;
  }
  // Each face as its sorted vertices, for the faces of one bucket.
  std::vector<std::vector<uint32_t>> sorted;
  std::vector<uint32_t> rank;
  for (size_t v = 0; v < vertex_count; ++v) {
    const uint32_t first = bucket_start[v], end = bucket_start[v + 1];
    if (end - first < 2) continue;
    sorted.resize(end - first);
    for (uint32_t i = first; i < end; ++i) {
      const uint32_t f = bucketed[i];
      const uint32_t* c = faces.corners.data() + soup.polygon_starts[f];
      sorted[i - first].assign(c, c + soup.corner_count(f));
      std::sort(sorted[i - first].begin(), sorted[i - first].end());
    }
    // By vertices, then file order: each duplicate follows the first face
    // with its vertices (a hub vertex's bucket may hold thousands).
    rank.resize(end - first);
    for (uint32_t i = 0; i < rank.size(); ++i) rank[i] = i;
    std::sort(rank.begin(), rank.end(), [&](uint32_t x, uint32_t y) { return sorted[x] != sorted[y] ? sorted[x] < sorted[y] : x < y; });
    for (size_t k = 1; k < rank.size(); ++k) {
      if (sorted[rank[k]] != sorted[rank[k - 1]]) continue;
      const uint32_t f = bucketed[first + rank[k]];
      faces.duplicate[f] = 1;
      faces.duplicate_of[f] = faces.duplicate[bucketed[first + rank[k - 1]]] ? faces.duplicate_of[bucketed[first + rank[k - 1]]]
                                                                            : bucketed[first + rank[k - 1]];
    }
  }
}

// One face's use of an edge, going from the vertex at `corner` to the next one.
// Filed under the edge's smaller vertex, it names the larger one.
struct EdgeUse {
  uint32_t other;  // the larger vertex
  uint32_t face;
  uint32_t corner_and_direction;  // index into Faces::corners << 1 | traversed from smaller to larger vertex

  uint32_t corner() const { return corner_and_direction >> 1; }
  bool forward() const { return corner_and_direction & 1; }
};

uint32_t next_corner(const PolygonSoup& soup, uint32_t face, uint32_t corner) {
  return corner + 1 == soup.polygon_starts[face + 1] ? soup.polygon_starts[face] : corner + 1;
}

// The stages of the analysis, in the order run() calls them; each reads what
// the earlier ones left in the members below.
class MeshAnalyser {
 public:
  // With `disposable` (the soup itself), its points are freed once merged
  // and its corners become the merged vertices' in place.
  MeshAnalyser(const PolygonSoup& soup, MeshAnalysis& analysis, PolygonSoup* disposable)
      : soup(soup),
        disposable(disposable),
        analysis(analysis),
        report(analysis.report),
        examples(analysis.report.examples),
        comps(analysis.report.components),
        triangles(analysis.triangles),
        triangle_face(analysis.triangle_face),
        merged(merge_coincident_points(soup.points)),
        face_count(soup.polygon_count()),
        vertex_count(merged.positions.size()),
        components(face_count),
        flips(face_count),
        fans(soup.corners.size()),
        border_graph(vertex_count) {}

  void run(const CheckOptions& options) {
    describe_file();
    if (disposable) std::vector<glm::dvec3>().swap(disposable->points);
    sort_faces();
    group_edges();
    label_components();
    find_non_manifold_vertices();
    count_border_loops();
    orient_faces();
    triangulate();
    summarise_components();
    release_topology();
    search_self_intersections(options);
    analysis.positions = std::move(merged.positions);
  }

 private:
  void describe_file();
  void sort_faces();
  void group_edges();
  void label_components();
  void find_non_manifold_vertices();
  void count_border_loops();
  void orient_faces();
  void triangulate();
  void summarise_components();
  void release_topology();
  void search_self_intersections(const CheckOptions& options);

  ElementRef vertex_ref(uint32_t v) const {
    const uint32_t p = merged.first_point[v];
    return ElementRef{p, soup.point_line(p)};
  }
  ElementRef face_ref(uint32_t f) const { return ElementRef{f, soup.polygon_line(f)}; }
  template <typename List>
  static bool room_for(const List& list) { return list.size() < MeshReport::kMaxExamples; }
  // Whether face f must flip: its parity class is the smaller one in its set
  // (ties keep the root's class).
  bool must_flip(uint32_t f) const {
    const auto& counts = parity_counts[flip_root[f]];
    const uint8_t keep = counts[1] > counts[0] ? 1 : 0;
    return parity_of[f] != keep;
  }

  const PolygonSoup& soup;
  PolygonSoup* disposable;
  MeshAnalysis& analysis;
  MeshReport& report;
  MeshReport::Examples& examples;
  std::vector<ComponentReport>& comps;
  std::vector<std::array<uint32_t, 3>>& triangles;
  std::vector<uint32_t>& triangle_face;
  MergedPoints merged;
  const size_t face_count, vertex_count;
  Faces faces;

  // group_edges
  struct EdgeRun {
    uint64_t key;
    uint32_t face;
    uint32_t uses;
  };
  std::vector<EdgeRun> edges;
  UnionFind components;                   // faces joined across any edge
  ParityUnionFind flips;                  // parity 1: the face must flip to agree with its set's root
  UnionFind fans;                         // corners joined across the manifold edges at their vertex
  UnionFind border_graph;                 // vertices joined by border edges
  std::vector<uint8_t> orientation_conflict, on_non_manifold_edge;
  std::vector<uint32_t> inconsistent_edge_faces;
  // label_components and later
  std::vector<uint32_t> component_of, component_of_vertex;
  std::vector<uint8_t> component_non_manifold, component_conflict;
  std::vector<size_t> component_inconsistent;
  // orient_faces
  std::vector<std::array<uint32_t, 2>> parity_counts;
  std::vector<uint8_t> parity_of;
  std::vector<uint32_t> flip_root;

};

void MeshAnalyser::describe_file() {
  report.path = soup.path;
  report.format = soup.format;
  report.file_vertices = soup.points.size();
  report.file_faces = face_count;
  report.merged_vertices = soup.points.size() - vertex_count;
  if (!soup.points.empty()) {
    report.bbox_min = report.bbox_max = soup.points[0];
    for (const glm::dvec3& p : soup.points) {
      report.bbox_min = glm::min(report.bbox_min, p);
      report.bbox_max = glm::max(report.bbox_max, p);
    }
  }
}

// Faces: degenerate, duplicate, or part of the topology.
void MeshAnalyser::sort_faces() {
  if (disposable) {
    for (uint32_t& corner : disposable->corners) corner = merged.vertex_of_point[corner];
    faces.corners = std::move(disposable->corners);
  } else {
    faces.corners.resize(soup.corners.size());
    for (size_t c = 0; c < soup.corners.size(); ++c) faces.corners[c] = merged.vertex_of_point[soup.corners[c]];
  }
  std::vector<uint32_t>().swap(merged.vertex_of_point);
  faces.repeats_vertex.assign(face_count, 0);
  faces.collinear.assign(face_count, 0);
  faces.duplicate.assign(face_count, 0);
  faces.duplicate_of.assign(face_count, kNone);
  std::vector<uint8_t> vertex_used(vertex_count, 0);
  for (uint32_t f = 0; f < face_count; ++f) {
    const uint32_t* v = faces.corners.data() + soup.polygon_starts[f];
    const uint32_t n = soup.corner_count(f);
    for (uint32_t k = 0; k < n; ++k) vertex_used[v[k]] = 1;
    faces.repeats_vertex[f] = has_repeated_vertex(v, n);
    faces.collinear[f] = !faces.repeats_vertex[f] && all_collinear(merged.positions, v, n);
    if (faces.repeats_vertex[f] || faces.collinear[f]) {
      ++report.degenerate_faces;
      if (room_for(examples.degenerate_faces)) examples.degenerate_faces.push_back(face_ref(f));
    }
  }
  report.vertices = size_t(std::count(vertex_used.begin(), vertex_used.end(), 1));
  report.isolated_vertices = vertex_count - report.vertices;
  find_duplicates(soup, vertex_count, faces);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.duplicate[f]) continue;
    ++report.duplicate_faces;
    if (room_for(examples.duplicate_faces)) examples.duplicate_faces.push_back({face_ref(f), face_ref(faces.duplicate_of[f])});
  }
}

// Edges: every face's use of every edge, grouped by edge.
void MeshAnalyser::group_edges() {
  orientation_conflict.assign(face_count, 0);
  on_non_manifold_edge.assign(vertex_count, 0);
  // A counting sort by the smaller vertex, then each vertex's few uses by
  // the larger one: linear, and in the order (edge, face) that a full sort
  // would give, since faces are taken in order.
  std::vector<uint32_t> bucket_start(vertex_count + 1, 0);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c)
      ++bucket_start[std::min(faces.corners[c], faces.corners[next_corner(soup, f, c)]) + 1];
  }
  for (size_t v = 0; v < vertex_count; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<EdgeUse> uses(bucket_start[vertex_count]);
  {
    std::vector<uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (uint32_t f = 0; f < face_count; ++f) {
      if (!faces.in_topology(f)) continue;
      for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c) {
        const uint32_t a = faces.corners[c], b = faces.corners[next_corner(soup, f, c)];
        uses[fill[std::min(a, b)]++] = {std::max(a, b), f, (c << 1) | uint32_t(a < b)};
      }
    }
  }
  for (size_t v = 0; v < vertex_count; ++v) {
    if (bucket_start[v + 1] - bucket_start[v] > 32) {  // a vertex of high degree, the hub of a fan
      std::sort(uses.begin() + bucket_start[v], uses.begin() + bucket_start[v + 1], [](const EdgeUse& x, const EdgeUse& y) {
        return x.other != y.other ? x.other < y.other : x.face < y.face;
      });
      continue;
    }
    for (uint32_t i = bucket_start[v] + 1; i < bucket_start[v + 1]; ++i) {
      const EdgeUse use = uses[i];
      uint32_t j = i;
      for (; j > bucket_start[v] && uses[j - 1].other > use.other; --j) uses[j] = uses[j - 1];
      uses[j] = use;  // insertion sort: stable, and most buckets hold a handful
    }
  }

  for (size_t i = 0, bucket = 0; i < uses.size();) {
    while (bucket_start[bucket + 1] <= i) ++bucket;  // the bucket, and so the smaller vertex, of use i
    const uint32_t a = uint32_t(bucket);
    size_t j = i + 1;
    while (j < bucket_start[bucket + 1] && uses[j].other == uses[i].other) ++j;
    const uint32_t b = uses[i].other;
    edges.push_back({(uint64_t(a) << 32) | b, uses[i].face, uint32_t(j - i)});
    for (size_t k = i + 1; k < j; ++k) components.unite(uses[i].face, uses[k].face);
    if (j - i == 1) {
      ++report.border_edges;
      border_graph.unite(a, b);
      if (room_for(examples.border_edges)) examples.border_edges.push_back({vertex_ref(a), vertex_ref(b)});
    } else if (j - i == 2) {
      const EdgeUse& x = uses[i];
      const EdgeUse& y = uses[i + 1];
      const bool same_direction = x.forward() == y.forward();
      if (same_direction) {
        ++report.inconsistent_edges;
        inconsistent_edge_faces.push_back(x.face);
      }
      if (!flips.unite(x.face, y.face, same_direction ? 1 : 0)) orientation_conflict[x.face] = 1;
      // Join the two faces' corners at each end of the edge.
      const uint32_t x_next = next_corner(soup, x.face, x.corner()), y_next = next_corner(soup, y.face, y.corner());
      fans.unite(x.corner(), same_direction ? y.corner() : y_next);
      fans.unite(x_next, same_direction ? y_next : y.corner());
    } else {
      ++report.non_manifold_edges;
      on_non_manifold_edge[a] = on_non_manifold_edge[b] = 1;
      if (room_for(examples.non_manifold_edges)) examples.non_manifold_edges.push_back({vertex_ref(a), vertex_ref(b)});
    }
    i = j;
  }
  std::vector<uint32_t>().swap(bucket_start);
  report.edges = edges.size();
  std::vector<EdgeUse>().swap(uses);  // the largest array; the edges and unions hold what is needed
}

// Components, numbered in order of their first face, and what each holds.
void MeshAnalyser::label_components() {
  component_of.assign(face_count, kNone);
  std::vector<uint32_t> component_of_root(face_count, kNone);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    uint32_t& id = component_of_root[components.find(f)];
    if (id == kNone) {
      id = uint32_t(report.components.size());
      report.components.emplace_back();
    }
    component_of[f] = id;
    ++report.components[id].faces;
  }
  component_non_manifold.assign(comps.size(), 0);
  component_conflict.assign(comps.size(), 0);
  component_inconsistent.assign(comps.size(), 0);
  for (const EdgeRun& e : edges) {
    ComponentReport& c = comps[component_of[e.face]];
    ++c.edges;
    if (e.uses == 1) ++c.border_edges;
    if (e.uses > 2) component_non_manifold[component_of[e.face]] = 1;
  }
  for (uint32_t f : inconsistent_edge_faces) ++component_inconsistent[component_of[f]];
  for (uint32_t f = 0; f < face_count; ++f)
    if (orientation_conflict[f]) component_conflict[component_of[f]] = 1;
}

// Vertices per component, and vertices whose faces form more than one fan.
void MeshAnalyser::find_non_manifold_vertices() {
  component_of_vertex.assign(vertex_count, kNone);
  std::vector<uint64_t> vertex_in_other_component;  // (component << 32) | vertex: only where components touch
  std::vector<uint32_t> fan_of_vertex(vertex_count, kNone);
  std::vector<uint8_t> several_fans(vertex_count, 0);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c) {
      const uint32_t v = faces.corners[c];
      if (component_of_vertex[v] == kNone) {
        component_of_vertex[v] = component_of[f];
        ++comps[component_of[f]].vertices;
      } else if (component_of_vertex[v] != component_of[f]) {
        vertex_in_other_component.push_back((uint64_t(component_of[f]) << 32) | v);
      }
      const uint32_t fan = fans.find(c);
      if (fan_of_vertex[v] == kNone) fan_of_vertex[v] = fan;
      else if (fan_of_vertex[v] != fan) several_fans[v] = 1;
    }
  }
  std::sort(vertex_in_other_component.begin(), vertex_in_other_component.end());
  vertex_in_other_component.erase(std::unique(vertex_in_other_component.begin(), vertex_in_other_component.end()),
                                  vertex_in_other_component.end());
  for (uint64_t cv : vertex_in_other_component) ++comps[cv >> 32].vertices;
  for (uint32_t v = 0; v < vertex_count; ++v) {
    if (!several_fans[v] || on_non_manifold_edge[v]) continue;
    ++report.non_manifold_vertices;
    if (room_for(examples.non_manifold_vertices)) examples.non_manifold_vertices.push_back(vertex_ref(v));
  }
  // A component is non-manifold at a vertex when two of the vertex's fans lie in it.
  {
    std::vector<std::pair<uint32_t, uint64_t>> vertex_fans;
    for (uint32_t f = 0; f < face_count; ++f) {
      if (!faces.in_topology(f)) continue;
      for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c) {
        const uint32_t v = faces.corners[c];
        if (several_fans[v] && !on_non_manifold_edge[v])
          vertex_fans.push_back({v, (uint64_t(component_of[f]) << 32) | fans.find(c)});
      }
    }
    std::sort(vertex_fans.begin(), vertex_fans.end());
    vertex_fans.erase(std::unique(vertex_fans.begin(), vertex_fans.end()), vertex_fans.end());
    for (size_t i = 1; i < vertex_fans.size(); ++i) {
      if (vertex_fans[i].first == vertex_fans[i - 1].first && (vertex_fans[i].second >> 32) == (vertex_fans[i - 1].second >> 32))
        component_non_manifold[vertex_fans[i].second >> 32] = 1;
    }
  }
}

// Border loops: the connected pieces of the border edges.
void MeshAnalyser::count_border_loops() {
  std::vector<uint8_t> loop_counted(vertex_count, 0);
  for (const EdgeRun& e : edges) {
    if (e.uses != 1) continue;
    const uint32_t root = border_graph.find(uint32_t(e.key >> 32));
    if (loop_counted[root]) continue;
    loop_counted[root] = 1;
    ++report.border_loops;
    ++comps[component_of[e.face]].border_loops;
  }
}

// Orientation: within each set of faces joined by manifold edges, flipping
// the smaller parity class makes them agree.
void MeshAnalyser::orient_faces() {
  parity_counts.assign(face_count, {0, 0});
  parity_of.assign(face_count, 0);
  flip_root.assign(face_count, kNone);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    const auto [root, parity] = flips.find(f);
    flip_root[f] = root;
    parity_of[f] = parity;
    ++parity_counts[root][parity];
  }
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f) || component_conflict[component_of[f]] || !must_flip(f)) continue;
    ++report.faces_to_flip;
    if (room_for(examples.faces_to_flip)) examples.faces_to_flip.push_back(face_ref(f));
  }
}

// Triangles for the geometric tests and the renderer, oriented as after the
// flips. Faces whose corners are collinear stay: a closed mesh needs them.
void MeshAnalyser::triangulate() {
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    const size_t first = triangles.size();
    triangulate_polygon(merged.positions, faces.corners.data() + soup.polygon_starts[f], soup.corner_count(f), triangles);
    const bool flip = must_flip(f) && !component_conflict[component_of[f]];
    for (size_t t = first; t < triangles.size(); ++t) {
      triangle_face.push_back(f);
      if (flip) std::swap(triangles[t][1], triangles[t][2]);
    }
  }
  report.triangles = triangles.size();
}

// Per component: closed, manifold, orientable, genus, outward.
void MeshAnalyser::summarise_components() {
  std::vector<uint8_t> closed_and_orientable(comps.size(), 0);
  for (size_t i = 0; i < comps.size(); ++i)
    closed_and_orientable[i] = comps[i].border_edges == 0 && !component_non_manifold[i] && !component_conflict[i];
  std::vector<uint32_t> component_of_triangle(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) component_of_triangle[t] = component_of[triangle_face[t]];
  const std::vector<uint8_t> facing_in =
      wrongly_facing_closed_components(merged.positions, triangles, component_of_triangle, comps.size(), closed_and_orientable);
  for (size_t i = 0; i < comps.size(); ++i) {
    ComponentReport& c = comps[i];
    c.euler_characteristic = int64_t(c.vertices) - int64_t(c.edges) + int64_t(c.faces);
    c.manifold = !component_non_manifold[i];
    c.closed = c.border_edges == 0 && c.manifold;
    c.orientable = !component_conflict[i];
    c.consistently_oriented = c.orientable && component_inconsistent[i] == 0;
    if (c.manifold && c.orientable) c.genus = (2 - c.euler_characteristic - int64_t(c.border_loops)) / 2;
    if (c.closed && c.orientable) {
      c.outward = !facing_in[i];
      if (!*c.outward) ++report.inward_components;
    }
    if (!c.orientable) ++report.non_orientable_components;
  }
  // The renderer gets closed components facing outward, so that it can cull
  // their back faces (the file's orientation stays in the report).
  for (size_t t = 0; t < triangles.size(); ++t) {
    const ComponentReport& c = comps[component_of[triangle_face[t]]];
    if (c.outward == false) std::swap(triangles[t][1], triangles[t][2]);
  }
  // V - E + F over the faces in the topology, each vertex once.
  const auto topology_vertices = std::count_if(component_of_vertex.begin(), component_of_vertex.end(),
                                               [](uint32_t c) { return c != kNone; });
  size_t topology_faces = 0;
  for (const ComponentReport& c : comps) topology_faces += c.faces;
  report.euler_characteristic = int64_t(topology_vertices) - int64_t(edges.size()) + int64_t(topology_faces);
}

// What only the topological stages need, freed before the search (the
// largest stage) allocates its own.
void MeshAnalyser::release_topology() {
  std::vector<EdgeRun>().swap(edges);
  components = UnionFind(0);
  flips = ParityUnionFind(0);
  fans = UnionFind(0);
  border_graph = UnionFind(0);
  std::vector<uint32_t>().swap(faces.corners);
  std::vector<uint32_t>().swap(component_of_vertex);
}

void MeshAnalyser::search_self_intersections(const CheckOptions& options) {
  if (options.self_intersection_seconds > 0.0) {
    const SelfIntersections found = find_self_intersections(merged.positions, triangles, triangle_face,
                                                            options.self_intersection_seconds, MeshReport::kMaxExamples);
    report.self_intersections.checked = true;
    report.self_intersections.complete = found.complete;
    report.self_intersections.face_pairs = found.face_pairs;
    report.self_intersections.seconds = found.seconds;
    for (const auto& [f, g] : found.examples) examples.self_intersections.push_back({face_ref(f), face_ref(g)});
  }
  report.self_intersections.time_limit_seconds = options.self_intersection_seconds;
}

}  // namespace

namespace {

MeshAnalysis analyse(const PolygonSoup& soup, PolygonSoup* disposable, const CheckOptions& options) {
  if (soup.corners.size() >= (size_t(1) << 31))
    throw InputError({soup.path, 0, 0}, "too large to check: more than 2^31 face corners");
  MeshAnalysis analysis;
  MeshAnalyser(soup, analysis, disposable).run(options);
  return analysis;
}

}  // namespace

MeshAnalysis analyse_mesh(const PolygonSoup& soup, const CheckOptions& options) { return analyse(soup, nullptr, options); }
MeshAnalysis analyse_mesh(PolygonSoup&& soup, const CheckOptions& options) { return analyse(soup, &soup, options); }
MeshReport check_mesh(const PolygonSoup& soup, const CheckOptions& options) { return analyse_mesh(soup, options).report; }
MeshReport check_mesh(PolygonSoup&& soup, const CheckOptions& options) { return analyse_mesh(std::move(soup), options).report; }

}  // namespace umbra
