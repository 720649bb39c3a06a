#pragma once
// Where a smooth mesh's light ends. Its shadow is the faces' (a silhouette
// edge's volume starts exactly where the triangles turn from the light), but
// its shading normals stand for the smooth surface the faces approximate,
// whose light ends where those normals turn from it: up to half a face
// further on, or before. Shaded by its normals and shadowed by its faces, a
// coarse sphere would end its light in a saw-tooth of lit facets against
// the shadow. So on the faces that touch the terminator the normals decide,
// as a ray tracer that moves its shadow rays' start off the faceted surface
// onto the smooth one decides (Hanika, "Hacking the Shadow Terminator", Ray
// Tracing Gems II, 2021): a face there that turns from the light still
// takes the light its normals give it, as long as nothing but its own
// mesh's surface, where the light's ray leaves it, stands in between. The
// GL (shaders.hpp) and the reference (ray_cast_render.cpp) decide alike;
// the shadow masks and every shadow cast on other surfaces stay the faces'.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

// Per triangle of `mesh`, the side of its plane the light is on, exactly
// (the orientation predicate): +1 the side its corners wind
// counter-clockwise round, -1 the other, 0 in the plane. On every core.
std::vector<int8_t> triangle_light_sides(const Mesh& mesh, const glm::dvec3& light);

// Per triangle of a smooth `mesh`, 1 where it is on the terminator: at one
// of its corners' points, a triangle round the point does not have the
// light strictly on the side `sides` (of triangle_light_sides) gives this
// one, and is shaded alike there (its normal at the point within 10 degrees
// of this corner's: smoothed together). On every core.
std::vector<uint8_t> terminator_triangles(const Mesh& mesh, const std::vector<int8_t>& sides);

}  // namespace umbra
