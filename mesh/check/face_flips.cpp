#include "mesh/check/face_flips.hpp"

#include <utility>

#include "mesh/check/polygon_triangulation.hpp"

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

FaceTriangles triangulate_faces(const PolygonSoup& soup, const FaceClasses& faces, const std::vector<glm::dvec3>& positions) {
  FaceTriangles out;
  size_t count = 0;  // a polygon of n corners makes n - 2 triangles
  for (uint32_t f = 0; f < soup.polygon_count(); ++f)
    if (faces.in_topology(f)) count += soup.corner_count(f) - 2;
  out.triangles.reserve(count);
  out.face.reserve(count);
  for (uint32_t f = 0; f < soup.polygon_count(); ++f) {
    if (!faces.in_topology(f)) continue;
    const size_t first = out.triangles.size();
    triangulate_polygon(positions, faces.corners.data() + soup.polygon_starts[f], soup.corner_count(f), out.triangles);
    out.face.insert(out.face.end(), out.triangles.size() - first, f);
  }
  return out;
}

void turn_flipped(FaceTriangles& triangles, const std::vector<uint8_t>& flip) {
  for (size_t t = 0; t < triangles.triangles.size(); ++t)
    if (flip[triangles.face[t]]) std::swap(triangles.triangles[t][1], triangles.triangles[t][2]);
}

}  // namespace umbra
