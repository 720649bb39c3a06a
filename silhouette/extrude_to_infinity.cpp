#include "silhouette/extrude_to_infinity.hpp"

namespace umbra {

ShadowVolume extrude_to_infinity(const std::vector<glm::dvec3>& loop, const glm::dvec3& light) {
  const uint32_t n = uint32_t(loop.size());
  ShadowVolume volume;
  volume.vertices.reserve(2 * n);
  for (const glm::dvec3& p : loop) volume.vertices.emplace_back(p, 1.0);
  for (const glm::dvec3& p : loop) volume.vertices.emplace_back(p - light, 0.0);  // P' at infinity
  const auto far = [n](uint32_t i) { return i + n; };

  volume.triangles.reserve(4 * n - 4);
  for (uint32_t i = 1; i + 1 < n; ++i) volume.triangles.push_back({0, i, i + 1});  // light cap
  for (uint32_t i = 1; i + 1 < n; ++i) volume.triangles.push_back({far(0), far(i + 1), far(i)});
  // Side quad of edge a->b (counter-clockwise from the light) is b, a, a', b':
  // its outward normal points away from the polygon's interior.
  for (uint32_t a = 0; a < n; ++a) {
    const uint32_t b = (a + 1) % n;
    volume.triangles.push_back({b, a, far(a)});
    volume.triangles.push_back({b, far(a), far(b)});
  }
  volume.light_cap_triangles = int(n) - 2;
  volume.dark_cap_triangles = int(n) - 2;
  volume.side_quads = int(n);
  return volume;
}

}  // namespace umbra
