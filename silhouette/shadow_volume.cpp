#include "silhouette/shadow_volume.hpp"

namespace umbra {

void append_volume(ShadowVolume& all, const ShadowVolume& part) {
  const uint32_t base = uint32_t(all.vertices.size());
  const uint32_t triangle_base = uint32_t(all.triangles.size());
  for (const uint32_t end : part.part_ends) all.part_ends.push_back(end + triangle_base);
  all.vertices.insert(all.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (const auto& t : part.triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  all.side_quads += part.side_quads;
  all.light_cap_triangles += part.light_cap_triangles;
  all.dark_cap_triangles += part.dark_cap_triangles;
}

}  // namespace umbra
