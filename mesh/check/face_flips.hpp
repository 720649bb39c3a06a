#pragma once
// The mesh check's orientation and triangles: which faces to flip so that
// neighbours agree (within each set of faces joined by manifold edges, the
// smaller parity class; ties keep the class of the set's root; nothing in a
// component that no flips can make agree), and the triangles turned.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/check/edge_groups.hpp"
#include "mesh/check/face_classes.hpp"
#include "mesh/check/polygon_triangulation.hpp"

namespace umbra {

// Per face: 1 when it must flip.
std::vector<uint8_t> faces_to_flip(const FaceClasses& faces, ParityUnionFind& flips, const std::vector<uint32_t>& component_of,
                                   const std::vector<uint8_t>& component_conflict);

// Turns the triangles of the faces marked in `flip`.
void turn_flipped(FaceTriangles& triangles, const std::vector<uint8_t>& flip);

}  // namespace umbra
