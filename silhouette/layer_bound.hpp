#pragma once
// How many of a mesh's triangles one ray from a light can cross, bounded from
// above: the most a mesh's shadow volume can add to a stencil count at any
// point (an edge-multiplicity volume counts every triangle between a point
// and the light, a silhouette volume only those turned away from it). The
// 8-bit stencil counts modulo 256, so volumes whose bounds sum to more than
// 255 must not share a count.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

// The directions from `light` are split into cells (one grid over the cone
// round the mesh's bounding sphere, or the six faces of a cube round the
// light when that cone is wide or the light is inside the sphere), each
// triangle is counted in every cell its footprint (the triangle clipped to
// the cell grid's pyramid of directions, projected) may overlap, and the
// bound is the largest count. Any ray lies in a cell, and every triangle it
// crosses was counted there, so no ray crosses more. The cells are about as
// many as the triangles; a cell that holds many footprints is split, since
// where rays graze the surface many edge-on triangles pass through a cell
// that no ray crosses more than a few of. Returns `limit` + 1 when the bound
// exceeds `limit`, and the triangle count without any grid when that is no
// more than `limit`.
int layer_bound(const std::vector<glm::dvec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles,
                const glm::dvec3& light, int limit);

// Runs of a mesh's faces in file order, [first, end), whose layer bounds are
// each at most `limit`: the whole mesh when it fits, else each half, and so
// on (a run of `limit` faces or fewer always fits). A mesh of many stacked
// layers is then cast as several volumes, each its own stencil batch.
struct FaceRun {
  uint32_t first = 0, end = 0;
  int bound = 0;
};
std::vector<FaceRun> layer_bounded_runs(const std::vector<glm::dvec3>& positions,
                                        const std::vector<std::array<uint32_t, 3>>& triangles, const glm::dvec3& light,
                                        int limit);

}  // namespace umbra
