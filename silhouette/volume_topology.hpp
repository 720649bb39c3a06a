#pragma once

#include "silhouette/shadow_volume.hpp"

namespace umbra {

// True when every edge is shared by exactly two triangles that run along it in
// opposite directions: the volume is a closed, consistently oriented surface,
// so the stencil count of every ray leaving it returns to zero.
bool is_closed_and_consistently_oriented(const ShadowVolume& volume);

// True when every directed edge occurs as often as its reverse: the volume has
// no boundary, so every ray crosses it inward as often as outward and the
// stencil count still returns to zero. This is what a mesh's volume is where
// two silhouette loops meet at a vertex (a torus seen at a slant): the side
// quads of both loops share the edge from that vertex to infinity, which is
// then used twice in each direction.
bool has_no_boundary(const ShadowVolume& volume);

}  // namespace umbra
