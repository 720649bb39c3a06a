#pragma once
// Vertices whose star cannot intersect itself, so that the self-intersection
// search may skip every pair of triangles sharing them.
//
// A vertex's star is simple here when its triangles form one closed fan
// (each edge from the vertex in exactly two of them, however they are wound)
// and some coordinate plane sees the fan turn once round the vertex, every
// triangle turning the same way. The projection is then one-to-one on the
// star: the projected triangles tile the plane round the vertex once, so two
// of them meet only along a shared edge's ray or at the vertex, and each is
// one-to-one on its triangle. Two triangles of the star therefore meet only
// along their shared edge or at the vertex, which the search does not count.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

// Per vertex, 1 when its star is simple. Only the triangles listed in
// `tested` (indices into `triangles`, none with collinear corners) count as
// its star; a vertex of more than 32 such triangles is not examined.
std::vector<uint8_t> find_simple_stars(const std::vector<glm::dvec3>& positions,
                                       const std::vector<std::array<uint32_t, 3>>& triangles,
                                       const std::vector<uint32_t>& tested);

}  // namespace umbra
