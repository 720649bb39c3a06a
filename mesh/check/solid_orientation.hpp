#pragma once
// Which way each closed component of a mesh should face: away from the solid
// it bounds. A shell nested in an even number of others (0, 2, ...) bounds
// solid inside it and should enclose positive volume; one nested in an odd
// number bounds a cavity (the inner shell of a hollow solid) and should
// enclose negative volume, as CGAL's orient_to_bound_a_volume decides. The
// check, the renderer and --repair all decide it here.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

enum class Facing : uint8_t {
  kRight,      // away from its solid (or not a closed shell: nothing to decide)
  kWrong,      // into its solid: turning it round puts it right
  kUndecided,  // no sound answer: it crosses a face, or one of the shells round it does
};

struct ShellFacing {
  std::vector<Facing> facing;  // per component
  // Per component, the volume its triangles enclose as given (turned where
  // `reversed` says): positive when they face away from what they enclose.
  std::vector<double> volume;
};
// Which way each closed component faces. `component_of[t]` numbers triangle
// t's component, below `count`; `closed[c]` says which are closed and
// consistently oriented; `tangled[c]` which cross a face, their own or
// another component's (or may: when no complete search says otherwise).
// With `reversed`, triangle t is read turned round (its corners 1 and 2
// swapped) where reversed[t] is set.
//
// A shell that crosses nothing divides space into an inside and an outside,
// and every other shell that crosses nothing lies wholly on one side of it:
// then its signed volume says which way it faces, and the winding number of
// each shell whose box holds it, at any of its vertices off that shell, says
// how deeply it is nested. A tangled shell has no such answer, nor has one
// inside a tangled shell: both are undecided.
//
// Volumes are summed about the centre of each component's own box, so a
// small solid far from the origin keeps its sign (summed about the origin,
// 1e9 away, its terms cancel to noise). Winding numbers are summed from solid
// angles (Van Oosterom and Strackee 1983), only where a component's box holds
// this one's.
ShellFacing facing_of_closed_components(const std::vector<glm::dvec3>& positions,
                                                const std::vector<std::array<uint32_t, 3>>& triangles,
                                                const std::vector<uint32_t>& component_of, size_t count,
                                                const std::vector<uint8_t>& closed, const std::vector<uint8_t>& tangled,
                                        const std::vector<uint8_t>* reversed = nullptr);

}  // namespace umbra
