#include "mesh/check/edge_groups.hpp"

#include "mesh/check/bucket_fill.hpp"
#include "mesh/unset_vector.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace umbra {
namespace {

// One face's use of an edge, going from the vertex at `corner` to the next
// one. Filed under the edge's smaller vertex, it names the larger one.
struct EdgeUse {
  uint32_t other;  // the larger vertex
  uint32_t face;
  uint32_t corner_and_direction;  // index into FaceClasses::corners << 1 | traversed from smaller to larger vertex

  uint32_t corner() const { return corner_and_direction >> 1; }
  bool forward() const { return corner_and_direction & 1; }
};

// Every use, bucketed by its smaller vertex (bucket v is uses[start[v],
// start[v + 1])), each bucket sorted by the larger vertex and then by face:
// the order a full sort of (edge, face) would give, since faces are taken in
// order.
UnsetVector<EdgeUse> sorted_uses(const PolygonSoup& soup, const FaceClasses& faces, std::vector<uint32_t>& start) {
  const size_t vertex_count = start.size() - 1;
  UnsetVector<EdgeUse> uses;
  fill_buckets<EdgeUse>(soup.polygon_count(), vertex_count, [&](uint32_t first_face, uint32_t end_face, const auto& put) {
    for (uint32_t f = first_face; f < end_face; ++f) {
      if (!faces.in_topology(f)) continue;
      for (uint32_t c = soup.polygon_starts[f]; c < soup.polygon_starts[f + 1]; ++c) {
        const uint32_t a = faces.corners[c], b = faces.corners[next_corner(soup, f, c)];
        put(std::min(a, b), EdgeUse{std::max(a, b), f, (c << 1) | uint32_t(a < b)});
      }
    }
  }, start, uses);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count, 4096), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t v = range.begin(); v < range.end(); ++v) {
      if (start[v + 1] - start[v] > 32) {  // a vertex of high degree, the hub of a fan
        std::sort(uses.begin() + start[v], uses.begin() + start[v + 1], [](const EdgeUse& x, const EdgeUse& y) {
          return x.other != y.other ? x.other < y.other : x.face < y.face;
        });
        continue;
      }
      for (uint32_t i = start[v] + 1; i < start[v + 1]; ++i) {
        const EdgeUse use = uses[i];
        uint32_t j = i;
        for (; j > start[v] && uses[j - 1].other > use.other; --j) uses[j] = uses[j - 1];
        uses[j] = use;  // insertion sort: stable, and most buckets hold a handful
      }
    }
  });
  return uses;
}

// Calls visit(a, b, i, j) for each edge a < b, in order, whose uses are
// uses[i, j).
template <typename Visit>
void for_each_edge(const UnsetVector<EdgeUse>& uses, const std::vector<uint32_t>& start, Visit visit) {
  for (size_t i = 0, bucket = 0; i < uses.size();) {
    while (start[bucket + 1] <= i) ++bucket;  // the bucket, and so the smaller vertex, of use i
    const uint32_t b = uses[i].other;
    size_t j = i + 1;
    while (j < start[bucket + 1] && uses[j].other == b) ++j;
    visit(uint32_t(bucket), b, i, j);
    i = j;
  }
}

}  // namespace

EdgeGroups group_edges(const PolygonSoup& soup, const FaceClasses& faces, size_t vertex_count, EdgeTable* face_edges) {
  const size_t face_count = soup.polygon_count();
  // The union-finds are made by the walks that fill them, on their cores.
  EdgeGroups g{{}, UnionFind(0), ParityUnionFind(0), UnionFind(0), {}, {}, {}};
  std::vector<uint32_t> start(vertex_count + 1, 0);
  const UnsetVector<EdgeUse> uses = sorted_uses(soup, faces, start);
  size_t edge_count = 0;  // reserved exactly: growing by doubling would hold half as much again
  for_each_edge(uses, start, [&](uint32_t, uint32_t, size_t, size_t) { ++edge_count; });
  g.edges.reserve(edge_count);
  if (face_edges) {
    face_edges->vertices.reserve(edge_count);
    face_edges->first_use.reserve(edge_count + 1);
    face_edges->uses.reserve(uses.size());
  }
  // Three walks over the edges, each on a core of its own where there are
  // three: faces and their orientations; corners into fans (the
  // largest of the union-finds, and independent); the edge table.
  tbb::parallel_invoke(
      [&] {
        g.components = UnionFind(face_count);
        g.flips = ParityUnionFind(face_count);
        g.orientation_conflict.assign(face_count, 0);
        g.on_non_manifold_edge.assign(vertex_count, 0);
        for_each_edge(uses, start, [&](uint32_t a, uint32_t b, size_t i, size_t j) {
          g.edges.push_back({a, b, uses[i].face, uint32_t(j - i)});
          for (size_t k = i + 1; k < j; ++k) g.components.unite(uses[i].face, uses[k].face);
          if (j - i == 2) {
            const EdgeUse& x = uses[i];
            const EdgeUse& y = uses[i + 1];
            const bool same_direction = x.forward() == y.forward();
            if (same_direction) g.inconsistent_edge_faces.push_back(x.face);
            if (!g.flips.unite(x.face, y.face, same_direction ? 1 : 0)) g.orientation_conflict[x.face] = 1;
          } else if (j - i > 2) {
            g.on_non_manifold_edge[a] = g.on_non_manifold_edge[b] = 1;
          }
        });
      },
      [&] {
        g.fans = UnionFind(faces.corners.size());
        for_each_edge(uses, start, [&](uint32_t, uint32_t, size_t i, size_t j) {
          if (j - i != 2) return;
          // Join the two faces' corners at each end of the edge.
          const EdgeUse& x = uses[i];
          const EdgeUse& y = uses[i + 1];
          const bool same_direction = x.forward() == y.forward();
          const uint32_t x_next = next_corner(soup, x.face, x.corner()), y_next = next_corner(soup, y.face, y.corner());
          g.fans.unite(x.corner(), same_direction ? y.corner() : y_next);
          g.fans.unite(x_next, same_direction ? y_next : y.corner());
        });
      },
      [&] {
        if (!face_edges) return;
        for_each_edge(uses, start, [&](uint32_t a, uint32_t b, size_t i, size_t j) {
          face_edges->vertices.push_back({a, b});
          for (size_t k = i; k < j; ++k) face_edges->uses.push_back(uses[k].face << 1 | uint32_t(uses[k].forward()));
          face_edges->first_use.push_back(uint32_t(face_edges->uses.size()));
        });
      });
  return g;
}

}  // namespace umbra
