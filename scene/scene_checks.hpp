#pragma once
// Checks that depend on where the lights are now (after --light-angle), so
// they run on the final scene rather than in the parser.

#include "scene/scene.hpp"

namespace umbra {

// Throws InputError at the sphere's line when a light is inside a sphere or on
// its surface: its tangent cone (docs/geometry.md) does not exist there. And at the
// mesh's line when a light is on a mesh's surface: the volume would need the
// direction from the light to itself. (A light inside a closed mesh is fine:
// its volume is then everything outside the mesh, which is the right shadow.)
void require_lights_off_casters(const Scene& scene);

}  // namespace umbra
