#pragma once
// A mesh's shadow volume as indices into the mesh's 2N vertices: v < N is
// mesh vertex v, v >= N is mesh vertex v - N at infinity, (P - L, 0). The
// vertices never change with the light, so a renderer keeps them in a static
// buffer and sends only these indices each frame.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "silhouette/shadow_volume.hpp"

namespace umbra {

struct MeshVolumeIndices {
  // Triangles, counter-clockwise seen from outside the volume: the first
  // `count` entries, every cap triangle before every side quad (so that
  // z-pass, which needs no caps, draws from 3 * (light_cap_triangles +
  // dark_cap_triangles) on). The buffer keeps its size across frames, so a
  // frame allocates nothing once it has grown to the volume's size.
  std::vector<uint32_t> buffer;
  size_t count = 0;
  int side_quads = 0;
  int light_cap_triangles = 0;  // the near cap
  int dark_cap_triangles = 0;

  void clear() {
    count = 0;
    side_quads = light_cap_triangles = dark_cap_triangles = 0;
  }
  // Room for n more indices after the first `count`, which it then counts.
  uint32_t* append(size_t n) {
    if (count + n > buffer.size()) buffer.resize(std::max(2 * buffer.size(), count + n + 1024));
    uint32_t* out = buffer.data() + count;
    count += n;
    return out;
  }
};

// The volume with its vertices (mesh vertices, then the same at infinity),
// as one part: for tests and `umbra volume`.
ShadowVolume with_vertices(const MeshVolumeIndices& indices, const std::vector<glm::dvec3>& positions,
                           const glm::dvec3& light);

}  // namespace umbra
