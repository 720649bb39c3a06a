#include "silhouette/extrude_to_infinity.hpp"

namespace umbra {

ShadowVolume extrude_to_infinity(const std::vector<glm::dvec3>& loop, const glm::dvec3& light,
                                 const std::optional<glm::dvec3>& centre) {
  const uint32_t n = uint32_t(loop.size());
  ShadowVolume volume;
  volume.vertices.reserve(2 * n + 2);
  for (const glm::dvec3& p : loop) volume.vertices.emplace_back(p, 1.0);
  for (const glm::dvec3& p : loop) volume.vertices.emplace_back(p - light, 0.0);  // P' at infinity
  const auto far = [n](uint32_t i) { return i + n; };

  volume.triangles.reserve(4 * n);
  if (centre) {
    const uint32_t c = 2 * n;
    volume.vertices.emplace_back(*centre, 1.0);
    volume.vertices.emplace_back(*centre - light, 0.0);
    for (uint32_t i = 0; i < n; ++i) volume.triangles.push_back({c, i, (i + 1) % n});  // light cap
    for (uint32_t i = 0; i < n; ++i) volume.triangles.push_back({c + 1, far((i + 1) % n), far(i)});
  } else {
    for (uint32_t i = 1; i + 1 < n; ++i) volume.triangles.push_back({0, i, i + 1});  // light cap
    for (uint32_t i = 1; i + 1 < n; ++i) volume.triangles.push_back({far(0), far(i + 1), far(i)});
  }
  const int cap_triangles = int(volume.triangles.size() / 2);
  // Side quad of edge a->b (counter-clockwise from the light) is b, a, a', b':
  // its outward normal points away from the polygon's interior. It is split
  // along the diagonal from the lesser end (its coordinates compared in
  // order) to the other's far copy, so that the quad of a neighbour sharing
  // the edge, which runs it b->a, is split alike: the two cover the same
  // pixels at the same depths, and cancel, even seen nearly edge-on.
  const auto lesser = [](const glm::dvec3& p, const glm::dvec3& q) {
    return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.z < q.z;
  };
  for (uint32_t a = 0; a < n; ++a) {
    const uint32_t b = (a + 1) % n;
    if (lesser(loop[a], loop[b])) {  // diagonal a-b'
      volume.triangles.push_back({b, a, far(b)});
      volume.triangles.push_back({a, far(a), far(b)});
    } else {  // diagonal b-a'
      volume.triangles.push_back({b, a, far(a)});
      volume.triangles.push_back({b, far(a), far(b)});
    }
  }
  volume.light_cap_triangles = cap_triangles;
  volume.dark_cap_triangles = cap_triangles;
  volume.side_quads = int(n);
  return volume;
}

}  // namespace umbra
