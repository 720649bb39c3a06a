#pragma once
// Normals for smooth shading where a file gives none: each triangle corner's
// normal is the mean of those of the triangles round its point that meet the
// triangle at no more than a crease angle. A scan is smooth all over; a CAD
// part keeps its sharp edges, where faces meet at more than the angle.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

// Per triangle corner, a unit normal: the mean of the unit normals of the
// triangles at the corner's point (the triangle itself included) whose
// planes turn from the triangle's by at most `crease_deg`, each weighted by
// its angle at the point (Thurmer and Wuthrich, "Computing vertex normals
// from polygonal meshes", 1998), so that how a surface is cut into
// triangles does not tilt it, and by its area, so that a large flat face
// keeps its own normal where slivers of a shallow bevel or fillet meet it
// (as Blender's Weighted Normal modifier weighs faces, by area and angle),
// rather than tilting each of its corners its own way and showing the seams
// between its triangles. A degenerate triangle adds nothing, and its
// corners take (0, 0, 0): drawn flat. Normals point to the side the
// triangle's corners wind counter-clockwise round.
std::vector<std::array<glm::vec3, 3>> crease_normals(const std::vector<glm::dvec3>& points,
                                                     const std::vector<std::array<uint32_t, 3>>& triangles, double crease_deg);

}  // namespace umbra
