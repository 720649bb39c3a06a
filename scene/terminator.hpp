#pragma once
// Where a smooth mesh's light ends. Its shadow is the faces' (a silhouette
// edge's volume starts exactly where the triangles turn from the light), but
// its shading normals are the points': near that edge they still turn to the
// light, and the lit side would end in a saw-tooth of bright triangles
// against the shadow, the shadow terminator of smooth shading on coarse
// meshes. So each point round which the triangles turn both ways takes none
// of the light, and the triangles that touch it fade to it: the lit side
// meets its shadow at nothing, as a smooth surface's does. The GL
// (SurfaceBuffers::use_light) and the reference (ray_cast_render.cpp) fade
// alike.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

// Per triangle of `mesh`, the side of its plane the light is on, exactly
// (the orientation predicate): +1 the side its corners wind
// counter-clockwise round, -1 the other, 0 in the plane. On every core.
std::vector<int8_t> triangle_light_sides(const Mesh& mesh, const glm::dvec3& light);

// Per triangle corner of a smooth `mesh`, 1 where the light fades to
// nothing: a triangle round the corner's point does not have the light
// strictly on the side `sides` (of triangle_light_sides) gives this one, and
// is shaded alike there (its normal at the point within 10 degrees of this
// corner's: smoothed together). On every core.
std::vector<std::array<uint8_t, 3>> terminator_corners(const Mesh& mesh, const std::vector<int8_t>& sides);

}  // namespace umbra
