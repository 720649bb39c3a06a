#pragma once
// Checks that depend on where the lights are now (after --light-angle), so
// they run on the final scene rather than in the parser.

#include "mesh/scene.hpp"

namespace umbra {

// Throws InputError at the sphere's line when a light is inside a sphere or on
// its surface: its tangent cone (spec 2.2) does not exist there.
void require_lights_outside_spheres(const Scene& scene);

}  // namespace umbra
