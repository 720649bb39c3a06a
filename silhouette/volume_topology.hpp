#pragma once

#include "silhouette/shadow_volume.hpp"

namespace umbra {

// True when every edge is shared by exactly two triangles that run along it in
// opposite directions: the volume is a closed, consistently oriented surface,
// so the stencil count of every ray leaving it returns to zero.
bool is_closed_and_consistently_oriented(const ShadowVolume& volume);

}  // namespace umbra
