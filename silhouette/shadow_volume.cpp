#include "silhouette/shadow_volume.hpp"

namespace umbra {

void append_volume(ShadowVolume& all, const ShadowVolume& part, bool with_caps) {
  const uint32_t base = uint32_t(all.vertices.size());
  all.vertices.insert(all.vertices.end(), part.vertices.begin(), part.vertices.end());
  const auto is_cap = [&](const std::array<uint32_t, 3>& t) {
    const double w = part.vertices[t[0]].w;
    return part.vertices[t[1]].w == w && part.vertices[t[2]].w == w;
  };
  for (const auto& t : part.triangles)
    if (with_caps || !is_cap(t)) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  all.side_quads += part.side_quads;
  if (!with_caps) return;
  all.light_cap_triangles += part.light_cap_triangles;
  all.dark_cap_triangles += part.dark_cap_triangles;
}

}  // namespace umbra
