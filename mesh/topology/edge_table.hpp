#pragma once
// Every edge of a triangle mesh with the faces along it, from one pass over
// the 3T directed edges: what says whether a mesh is closed and consistently
// oriented, and what its shadow volume's side quads come from.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace umbra {

struct EdgeTable {
  // Edge e joins vertices[e][0] < vertices[e][1]. Its uses (one per face
  // side along it) are uses[first_use[e] .. first_use[e + 1]), each
  // face << 1 | 1 when that face runs from vertices[e][0] to vertices[e][1],
  // face << 1 otherwise. Edges are sorted by their vertices.
  std::vector<std::array<uint32_t, 2>> vertices;
  std::vector<uint32_t> first_use{0};
  std::vector<uint32_t> uses;

  size_t size() const { return vertices.size(); }
  uint32_t use_count(size_t e) const { return first_use[e + 1] - first_use[e]; }
  static uint32_t face_of(uint32_t use) { return use >> 1; }
  static bool runs_forward(uint32_t use) { return use & 1; }
};

// Requires every triangle's three vertices to be distinct and below
// `vertex_count`. Buckets the directed edges by their smaller vertex (a
// counting sort), then sorts each vertex's few edges: linear in the mesh.
EdgeTable build_edge_table(const std::vector<std::array<uint32_t, 3>>& triangles, size_t vertex_count);

}  // namespace umbra
