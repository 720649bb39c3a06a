#pragma once
// A shadow volume as a closed triangle surface in homogeneous coordinates:
// vertices at infinity are (P - L, 0) (Everitt and Kilgard), so the volume is
// unbounded yet closed, and needs a projection with its far plane at infinity.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

namespace umbra {

struct ShadowVolume {
  std::vector<glm::dvec4> vertices;                  // w = 1: finite, w = 0: at infinity
  std::vector<std::array<uint32_t, 3>> triangles;    // counter-clockwise seen from outside
  int side_quads = 0;           // each is two of the triangles
  int light_cap_triangles = 0;  // the finite cap, facing the light
  int dark_cap_triangles = 0;   // the cap at infinity
};

}  // namespace umbra

namespace umbra {

// Appends `part` to `all` (its indices shifted), summing the face counts.
// Without caps, only its side quads (for z-pass): a cap is a triangle whose
// vertices are all finite or all at infinity.
void append_volume(ShadowVolume& all, const ShadowVolume& part, bool with_caps = true);

}  // namespace umbra
