#pragma once
// Helpers for tests that compare shadow volumes as geometry, independent of
// vertex numbering.

#include <algorithm>
#include <array>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "silhouette/shadow_volume.hpp"

namespace umbra::test {

using Face = std::array<std::array<double, 4>, 3>;

// Each oriented triangle as its three homogeneous points, rotated so the
// smallest comes first (which keeps the orientation), then all sorted.
inline std::vector<Face> oriented_faces(const ShadowVolume& v) {
  std::vector<Face> faces;
  for (const auto& t : v.triangles) {
    Face f;
    for (int i = 0; i < 3; ++i) {
      const glm::dvec4& p = v.vertices[t[size_t(i)]];
      f[size_t(i)] = {p.x, p.y, p.z, p.w};
    }
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// The outward normal of a finite triangle (all w = 1) of the volume.
inline glm::dvec3 face_normal(const ShadowVolume& v, const std::array<uint32_t, 3>& t) {
  const glm::dvec3 a(v.vertices[t[0]]), b(v.vertices[t[1]]), c(v.vertices[t[2]]);
  return glm::cross(b - a, c - a);
}

}  // namespace umbra::test
