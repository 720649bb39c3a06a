#pragma once
// The mesh check's orientation and triangles: which faces to flip so that
// neighbours agree (within each set of faces joined by manifold edges, the
// smaller parity class; ties keep the class of the set's root; nothing in a
// component that no flips can make agree), and each face as triangles.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/check/edge_groups.hpp"
#include "mesh/check/face_classes.hpp"

namespace umbra {

// Per face: 1 when it must flip.
std::vector<uint8_t> faces_to_flip(const FaceClasses& faces, ParityUnionFind& flips, const std::vector<uint32_t>& component_of,
                                   const std::vector<uint8_t>& component_conflict);

struct FaceTriangles {
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> face;  // the file's face each triangle comes from
};
// The faces in the topology as triangles, as the file winds them. Faces
// whose corners are collinear stay: a closed mesh needs them.
FaceTriangles triangulate_faces(const PolygonSoup& soup, const FaceClasses& faces, const std::vector<glm::dvec3>& positions);

// Turns the triangles of the faces marked in `flip`.
void turn_flipped(FaceTriangles& triangles, const std::vector<uint8_t>& flip);

}  // namespace umbra
