#include "silhouette/mesh_volume.hpp"

#include "silhouette/classify_faces.hpp"
#include "silhouette/triangle_volume.hpp"

namespace umbra {

std::vector<std::array<uint32_t, 2>> silhouette_edges(const MeshAdjacency& mesh, const std::vector<uint8_t>& facing) {
  std::vector<std::array<uint32_t, 2>> edges;
  for (const MeshAdjacency::Edge& e : mesh.edges) {
    if (facing[e.left_face] == facing[e.right_face]) continue;
    edges.push_back(facing[e.left_face] ? std::array<uint32_t, 2>{e.from, e.to} : std::array<uint32_t, 2>{e.to, e.from});
  }
  return edges;
}

void mesh_volume_indices(const MeshAdjacency& mesh, const glm::dvec3& light, std::vector<uint8_t>& facing,
                         MeshVolumeIndices& volume) {
  classify_faces(mesh, light, facing);
  const uint32_t far = uint32_t(mesh.positions.size());  // offset of the vertices at infinity
  std::vector<uint32_t>& out = volume.indices;
  out.clear();
  volume.light_cap_triangles = volume.dark_cap_triangles = volume.side_quads = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (facing[t]) continue;
    const auto& tri = mesh.triangles[t];
    // The near cap is the faces that turn away from the light, reversed so
    // that they face it: the volume starts behind the mesh's lit side, which
    // is then never on its boundary (no self-shadowing where rasterisation
    // rounds differently for a surface and its cap, as at outlines).
    out.insert(out.end(), {tri[0], tri[2], tri[1]});
    ++volume.light_cap_triangles;
    // The far cap is the same faces at infinity, already facing away.
    out.insert(out.end(), {tri[0] + far, tri[1] + far, tri[2] + far});
    ++volume.dark_cap_triangles;
  }
  for (const MeshAdjacency::Edge& e : mesh.edges) {
    if (facing[e.left_face] == facing[e.right_face]) continue;
    // a -> b as the facing face runs along it (the reversed non-facing face
    // of the near cap runs a -> b too): seen from the light that is
    // counter-clockwise, so the quad (b, a, a', b') faces outward, as for a
    // triangle's sides (extrude_to_infinity).
    const uint32_t a = facing[e.left_face] ? e.from : e.to;
    const uint32_t b = facing[e.left_face] ? e.to : e.from;
    out.insert(out.end(), {b, a, a + far, b, a + far, b + far});
    ++volume.side_quads;
  }
}

ShadowVolume mesh_shadow_volume(const MeshAdjacency& mesh, const glm::dvec3& light) {
  std::vector<uint8_t> facing;
  MeshVolumeIndices indices;
  mesh_volume_indices(mesh, light, facing, indices);
  ShadowVolume volume;
  for (const glm::dvec3& p : mesh.positions) volume.vertices.emplace_back(p, 1.0);
  for (const glm::dvec3& p : mesh.positions) volume.vertices.emplace_back(p - light, 0.0);
  for (size_t i = 0; i < indices.indices.size(); i += 3)
    volume.triangles.push_back({indices.indices[i], indices.indices[i + 1], indices.indices[i + 2]});
  volume.side_quads = indices.side_quads;
  volume.light_cap_triangles = indices.light_cap_triangles;
  volume.dark_cap_triangles = indices.dark_cap_triangles;
  return volume;
}

ShadowVolume per_triangle_volume(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<uint32_t, 3>>& triangles, const glm::dvec3& light) {
  ShadowVolume all;
  for (const auto& t : triangles)
    if (auto volume = triangle_volume(positions[t[0]], positions[t[1]], positions[t[2]], light)) append_volume(all, *volume);
  return all;
}

}  // namespace umbra
