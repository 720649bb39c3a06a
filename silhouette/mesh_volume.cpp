#include "silhouette/mesh_volume.hpp"

#include "silhouette/light_facing.hpp"
#include "silhouette/parallel_append.hpp"
#include "silhouette/triangle_volume.hpp"

namespace umbra {

namespace {

// Edge e as (a, b) in the direction its face that faces the light runs along
// it, when it is a silhouette edge (its two faces disagree).
inline bool oriented_silhouette_edge(const MeshAdjacency& mesh, const uint8_t* facing, size_t e, uint32_t& a, uint32_t& b) {
  const auto [left, right] = mesh.edge_faces[e];
  if (facing[left] == facing[right]) return false;
  const auto [from, to] = mesh.edge_vertices[e];
  a = facing[left] ? from : to;
  b = facing[left] ? to : from;
  return true;
}

}  // namespace

std::vector<std::array<uint32_t, 2>> silhouette_edges(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing) {
  std::vector<std::array<uint32_t, 2>> edges;
  uint32_t a = 0, b = 0;
  for (size_t e = 0; e < mesh.edge_faces.size(); ++e)
    if (oriented_silhouette_edge(mesh, facing.data(), e, a, b)) edges.push_back({a, b});
  return edges;
}

void append_silhouette_caps(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing, MeshVolumeIndices& volume) {
  const uint32_t far = uint32_t(mesh.positions.size());  // offset of the vertices at infinity
  // The near cap is the faces that turn away from the light, reversed so
  // that they face it: the volume starts behind the mesh's lit side, which
  // is then never on its boundary (no self-shadowing where rasterisation
  // rounds differently for a surface and its cap, as at outlines). The far
  // cap is the same faces at infinity, already facing away.
  const size_t added = append_in_order(
      volume, mesh.triangles.size(), [&](size_t t) { return facing[t] ? size_t(0) : size_t(6); },
      [&](size_t t, uint32_t* out) {
        const auto& tri = mesh.triangles[t];
        out[0] = tri[0], out[1] = tri[2], out[2] = tri[1];
        out[3] = tri[0] + far, out[4] = tri[1] + far, out[5] = tri[2] + far;
      });
  volume.light_cap_triangles += int(added / 6);
  volume.dark_cap_triangles += int(added / 6);
}

void append_silhouette_quads(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing, MeshVolumeIndices& volume) {
  const uint32_t far = uint32_t(mesh.positions.size());
  // a -> b as the facing face runs along it (the reversed near-cap face runs
  // a -> b too): seen from the light that is counter-clockwise, so the quad
  // (b, a, a', b') faces outward, as for a triangle's sides
  // (extrude_to_infinity).
  const size_t added = append_in_order(
      volume, mesh.edge_faces.size(),
      [&](size_t e) {
        uint32_t a = 0, b = 0;
        return oriented_silhouette_edge(mesh, facing.data(), e, a, b) ? size_t(6) : size_t(0);
      },
      [&](size_t e, uint32_t* out) {
        uint32_t a = 0, b = 0;
        oriented_silhouette_edge(mesh, facing.data(), e, a, b);
        out[0] = b, out[1] = a, out[2] = a + far;
        out[3] = b, out[4] = a + far, out[5] = b + far;
      });
  volume.side_quads += int(added / 6);
}

void mesh_volume_indices(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing,
                         MeshVolumeIndices& volume) {
  classify_light_facing(mesh, light, facing);
  volume.clear();
  append_silhouette_caps(mesh, facing, volume);
  append_silhouette_quads(mesh, facing, volume);
}

ShadowVolume mesh_shadow_volume(const MeshAdjacency& mesh, const glm::dvec3& light) {
  std::vector<uint8_t> facing;
  MeshVolumeIndices indices;
  mesh_volume_indices(mesh, light, facing, indices);
  return with_vertices(indices, mesh.positions, light);
}

ShadowVolume per_triangle_volume(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<uint32_t, 3>>& triangles, const glm::dvec3& light) {
  ShadowVolume all;
  for (const auto& t : triangles)
    if (auto volume = triangle_volume(positions[t[0]], positions[t[1]], positions[t[2]], light)) append_volume(all, *volume);
  return all;
}

}  // namespace umbra
