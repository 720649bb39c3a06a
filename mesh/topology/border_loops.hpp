#pragma once
// The holes of a mesh, per component: the cycles of each component's border
// edges (edges with one face), counted per connected piece of them as its
// cycle rank E - V + 1, and at least 1 (a piece that ends on a non-manifold
// edge is still a hole). Two loops that touch at a vertex are two, and
// components that share a vertex each keep their own. The check and the renderer's
// topology both count them here.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace umbra {

struct BorderEdge {
  uint32_t component;  // any number below the component count
  uint32_t a, b;       // its vertices, below the vertex count
};

// Per component, how many loops its border edges make.
std::vector<size_t> border_loops_per_component(std::vector<BorderEdge> border, size_t component_count, size_t vertex_count);

}  // namespace umbra
