#include "mesh/check/face_flips.hpp"

#include <utility>

namespace umbra {

std::vector<uint8_t> faces_to_flip(const FaceClasses& faces, ParityUnionFind& flips, const std::vector<uint32_t>& component_of,
                                   const std::vector<uint8_t>& component_conflict) {
  const size_t face_count = faces.repeats_vertex.size();
  std::vector<std::array<uint32_t, 2>> parity_counts(face_count, {0, 0});
  std::vector<uint8_t> parity_of(face_count, 0);
  std::vector<uint32_t> root_of(face_count, 0);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f)) continue;
    const auto [root, parity] = flips.find(f);
    root_of[f] = root;
    parity_of[f] = parity;
    ++parity_counts[root][parity];
  }
  std::vector<uint8_t> flip(face_count, 0);
  for (uint32_t f = 0; f < face_count; ++f) {
    if (!faces.in_topology(f) || component_conflict[component_of[f]]) continue;
    const auto& counts = parity_counts[root_of[f]];
    const uint8_t keep = counts[1] > counts[0] ? 1 : 0;
    flip[f] = parity_of[f] != keep;
  }
  return flip;
}

void turn_flipped(FaceTriangles& triangles, const std::vector<uint8_t>& flip) {
  for (size_t t = 0; t < triangles.triangles.size(); ++t)
    if (flip[triangles.face[t]]) std::swap(triangles.triangles[t][1], triangles.triangles[t][2]);
}

}  // namespace umbra
