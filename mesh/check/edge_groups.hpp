#pragma once
// The mesh check's pass over the edges: every use of every edge by the faces
// in the topology, grouped by edge with a counting sort on the smaller vertex
// (linear), and what the groups say: which faces are joined, which must flip
// to agree with their neighbours, which corners share a fan round their
// vertex.

#include <cstdint>
#include <vector>

#include "mesh/check/face_classes.hpp"
#include "mesh/io/polygon_soup.hpp"
#include "mesh/topology/edge_table.hpp"
#include "mesh/topology/union_find.hpp"

namespace umbra {

// An edge a < b, the first face (in file order) along it, and how many face
// sides run along it: 1 a border, 2 manifold, more non-manifold.
struct EdgeRun {
  uint32_t a, b;
  uint32_t face;
  uint32_t uses;
};

struct EdgeGroups {
  std::vector<EdgeRun> edges;  // sorted by (a, b)
  UnionFind components;        // faces joined across any edge
  ParityUnionFind flips;       // parity 1: the face must flip to agree with its set's root
  UnionFind fans;              // corners joined across the manifold edges at their vertex
  std::vector<uint8_t> orientation_conflict;      // per face: no flips can make its set agree
  std::vector<uint8_t> on_non_manifold_edge;      // per vertex
  std::vector<uint32_t> inconsistent_edge_faces;  // a face of each edge two faces run the same way
};

// With `face_edges`, also every edge with each face's use of it, as an edge
// table over the faces (see triangle_topology.hpp).
EdgeGroups group_edges(const PolygonSoup& soup, const FaceClasses& faces, size_t vertex_count,
                       EdgeTable* face_edges = nullptr);

// The corner after `corner` round `face`.
inline uint32_t next_corner(const PolygonSoup& soup, uint32_t face, uint32_t corner) {
  return corner + 1 == soup.polygon_starts[face + 1] ? soup.polygon_starts[face] : corner + 1;
}

}  // namespace umbra
