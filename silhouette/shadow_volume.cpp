#include "silhouette/shadow_volume.hpp"

namespace umbra {

void append_volume(ShadowVolume& all, const ShadowVolume& part, bool with_caps) {
  const uint32_t base = uint32_t(all.vertices.size());
  all.vertices.insert(all.vertices.end(), part.vertices.begin(), part.vertices.end());
  const auto is_cap = [&](const std::array<uint32_t, 3>& t) {
    const double w = part.vertices[t[0]].w;
    return part.vertices[t[1]].w == w && part.vertices[t[2]].w == w;
  };
  // kept[i]: where part's triangle i lands in all, had it been kept.
  std::vector<uint32_t> kept(part.triangles.size() + 1);
  for (size_t i = 0; i < part.triangles.size(); ++i) {
    kept[i] = uint32_t(all.triangles.size());
    const auto& t = part.triangles[i];
    if (with_caps || !is_cap(t)) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  kept.back() = uint32_t(all.triangles.size());
  for (const uint32_t end : part.part_ends) all.part_ends.push_back(kept[end]);
  all.side_quads += part.side_quads;
  if (!with_caps) return;
  all.light_cap_triangles += part.light_cap_triangles;
  all.dark_cap_triangles += part.dark_cap_triangles;
}

}  // namespace umbra
