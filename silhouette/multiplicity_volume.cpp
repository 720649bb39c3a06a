#include "silhouette/multiplicity_volume.hpp"

#include <cstdlib>
#include <limits>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "silhouette/parallel_append.hpp"

namespace umbra {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// A use's share of its edge's multiplicity: the face's side, negated when the
// face runs from the edge's second vertex to its first.
inline int share(const std::vector<int8_t>& side, uint32_t use) {
  const int s = side[EdgeTable::face_of(use)];
  return EdgeTable::runs_forward(use) ? s : -s;
}

// |m| copies of edge (u, v)'s side quad at `out`: for m > 0 the oriented
// faces run u -> v, counter-clockwise seen from the light, so the quad is
// (v, u, u', v') as for a triangle's sides (extrude_to_infinity); for m < 0
// the reverse.
inline void write_quads(uint32_t u, uint32_t v, int m, uint32_t far, uint32_t* out) {
  if (m < 0) std::swap(u, v);
  for (int k = std::abs(m); k > 0; --k, out += 6) {
    out[0] = v, out[1] = u, out[2] = u + far;
    out[3] = v, out[4] = u + far, out[5] = v + far;
  }
}

}  // namespace

MultiplicityAdjacency build_multiplicity_adjacency(const std::vector<glm::dvec3>& positions,
                                                   const std::vector<std::array<uint32_t, 3>>& triangles,
                                                   const EdgeTable& edges, const std::vector<uint8_t>& in_subset) {
  MultiplicityAdjacency mesh;
  std::vector<uint32_t> local(triangles.size(), kNone);
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (!in_subset[t]) continue;
    local[t] = uint32_t(mesh.triangles.size());
    const auto& tri = triangles[t];
    mesh.triangles.push_back(tri);
    mesh.planes.push_back(face_plane(positions[tri[0]], positions[tri[1]], positions[tri[2]]));
  }
  std::vector<uint32_t> kept;  // the uses of one edge by the subset's faces, renumbered
  for (size_t e = 0; e < edges.size(); ++e) {
    kept.clear();
    for (uint32_t k = edges.first_use[e]; k < edges.first_use[e + 1]; ++k) {
      const uint32_t use = edges.uses[k];
      if (local[EdgeTable::face_of(use)] != kNone) kept.push_back(local[EdgeTable::face_of(use)] << 1 | (use & 1));
    }
    if (kept.empty()) continue;
    if (kept.size() == 2) {
      mesh.pair_uses.push_back({kept[0], kept[1]});
      mesh.pair_vertices.push_back(edges.vertices[e]);
      continue;
    }
    mesh.other_uses.insert(mesh.other_uses.end(), kept.begin(), kept.end());
    mesh.other_first_use.push_back(uint32_t(mesh.other_uses.size()));
    mesh.other_vertices.push_back(edges.vertices[e]);
  }
  return mesh;
}

void classify_light_sides(const std::vector<glm::dvec3>& positions, const MultiplicityAdjacency& mesh,
                          const glm::dvec3& light, std::vector<int8_t>& side) {
  side.resize(mesh.triangles.size());
  const double light_distance = glm::length(light);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), kClassifyBlock), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t < r.end(); ++t) {
      const auto& tri = mesh.triangles[t];
      side[t] = int8_t(light_side(mesh.planes[t], positions[tri[0]], positions[tri[1]], positions[tri[2]], light,
                                  light_distance));
    }
  });
}

void append_multiplicity_caps(const MultiplicityAdjacency& mesh, const std::vector<int8_t>& side, uint32_t far,
                              MeshVolumeIndices& volume) {
  const size_t added = append_in_order(
      volume, mesh.triangles.size(), [&](size_t t) { return side[t] == 0 ? size_t(0) : size_t(6); },  // in the light's plane: none
      [&](size_t t, uint32_t* out) {
        const auto& tri = mesh.triangles[t];
        // Oriented toward the light: counter-clockwise seen from it.
        const uint32_t a = tri[0], b = side[t] > 0 ? tri[1] : tri[2], c = side[t] > 0 ? tri[2] : tri[1];
        out[0] = a, out[1] = b, out[2] = c;                    // light cap, facing the light
        out[3] = a + far, out[4] = c + far, out[5] = b + far;  // dark cap, facing away
      });
  volume.light_cap_triangles += int(added / 6);
  volume.dark_cap_triangles += int(added / 6);
}

void append_multiplicity_quads(const MultiplicityAdjacency& mesh, const std::vector<int8_t>& side, uint32_t far,
                               MeshVolumeIndices& volume) {
  const auto pair_m = [&](size_t e) { return share(side, mesh.pair_uses[e][0]) + share(side, mesh.pair_uses[e][1]); };
  const auto other_m = [&](size_t e) {
    int m = 0;
    for (uint32_t k = mesh.other_first_use[e]; k < mesh.other_first_use[e + 1]; ++k) m += share(side, mesh.other_uses[k]);
    return m;
  };
  size_t added = append_in_order(
      volume, mesh.pair_uses.size(), [&](size_t e) { return 6 * size_t(std::abs(pair_m(e))); },
      [&](size_t e, uint32_t* out) { write_quads(mesh.pair_vertices[e][0], mesh.pair_vertices[e][1], pair_m(e), far, out); });
  added += append_in_order(
      volume, mesh.other_vertices.size(), [&](size_t e) { return 6 * size_t(std::abs(other_m(e))); },
      [&](size_t e, uint32_t* out) { write_quads(mesh.other_vertices[e][0], mesh.other_vertices[e][1], other_m(e), far, out); });
  volume.side_quads += int(added / 6);
}

ShadowVolume multiplicity_shadow_volume(const std::vector<glm::dvec3>& positions, const MultiplicityAdjacency& mesh,
                                        const glm::dvec3& light) {
  std::vector<int8_t> side;
  classify_light_sides(positions, mesh, light, side);
  MeshVolumeIndices indices;
  const uint32_t far = uint32_t(positions.size());
  append_multiplicity_caps(mesh, side, far, indices);
  append_multiplicity_quads(mesh, side, far, indices);
  return with_vertices(indices, positions, light);
}

}  // namespace umbra
