#pragma once
// How far a light's shadow volumes must reach. Extruded to infinity, a
// volume's side quads run from the caster to the light's vanishing point,
// across much of the frame, where a rasteriser walks them pixel by pixel
// however little they count. Stopping them past the last surface they can
// shadow gives every count the same value and draws far fewer pixels.

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

// The scale s to extrude a light's volumes by: each caster point P goes to
// L + s (P - L) instead of to infinity, the far cap with it; infinity when no
// finite s is sure to do. `casters` is the box round every caster the light's
// volumes are made from, `region` a box round every surface and the
// near-plane rectangle.
//
// Why it is exact: a point X of `region` inside the infinite volume is
// L + t (P - L) for a caster point P and some t >= 1, and lies inside the
// finite volume when t < s. Along an axis where the light lies beyond every
// caster (above them, say), X being no lower than `region`'s floor bounds t
// by (L.z - region.lo.z) / (L.z - casters.hi.z); s is the least such bound
// over the six faces, times a margin. Both volumes then hold the same points
// of `region`, and the same side faces there. z-fail, counting a closed
// volume's faces beyond the surface seen, tells whether the volume holds
// it, and the finite volume is as closed as the infinite one; z-pass counts
// the side faces between the near plane and the surface, a segment that
// stays inside `region`, which is convex.
double volume_reach(const glm::dvec3& light, const SceneBounds& casters, const SceneBounds& region);

// A finite reach however the light lies among the casters, for a camera
// that cannot draw a volume at infinity (an orthographic one): the least s
// past which every point of `region`'s bounding sphere (centre C, radius
// R) lies, margin included: s = (|L - C| + R) / d, d a lower bound on the
// light's distance from every caster point (nearest_surface_distance). A
// point X of the sphere inside the infinite volume is L + t (P - L) with
// |X - L| <= |L - C| + R and |P - L| >= d, so t < s; and the finite volume
// is the union of the segments from P to L + s (P - L), exactly: its far
// cap is the casters' triangles scaled about L by the one s, which maps a
// triangle onto a triangle. Infinity where d is 0 (a light on a surface).
double finite_volume_reach(const glm::dvec3& light, const SceneBounds& region, double nearest_caster);

// The margin: the far cap lies beyond `region`'s face by at least a tenth of
// the light's distance from that face, far past depth-buffer rounding. (A
// quarter, as first chosen, cost the staged engine 0.1 s of its 0.6 s on
// llvmpipe, in the volumes' part past the floor; bench/render_memory_benchmark.sh.)
inline constexpr double kVolumeReachMargin = 1.1;

}  // namespace umbra
