#pragma once
// A light's caster entries in the render plan: each sphere's, triangle's and
// mesh's shadow volume from that light and the phrase --explain says of it,
// or why it has none; and the light's volumes gathered for drawing.

#include <cstddef>

#include "render/render_plan.hpp"

namespace umbra {

// A sphere's volume: its tangent circle as a `segments`-gon.
CasterEntry sphere_entry(const Sphere& s, const Light& light, int segments);
// A triangle's three side quads and caps, or none where it is degenerate or
// seen edge-on by the light.
CasterEntry triangle_entry(const Triangle& t, const Light& light);
// A mesh's entry. Its volume goes to light_plan.mesh_volumes[slot], whose
// index buffer is kept from the previous frame when there is one; with
// --method triangles, every triangle's own volume instead.
CasterEntry mesh_entry(const Scene& scene, size_t index, const MeshCaster& caster, const Light& light, LightPlan& light_plan,
                       size_t& slot, MeshCasterScratch& scratch, bool per_triangle_asked);
// A caster that culling left out: its volume cannot reach the view.
CasterEntry culled_entry(const char* kind, const FileLoc& where);
// Every sphere's and triangle's volume in lp.all_volumes, in file order: one
// draw call (the meshes' volumes are drawn from their own buffers).
void gather_volumes(LightPlan& lp);
// Empties a light's sphere and triangle volumes (not its mesh volumes).
void clear_volumes(LightPlan& lp);

}  // namespace umbra
