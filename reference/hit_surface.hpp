#pragma once
// What a ray hit: the object's material, and for a mesh triangle, the mesh
// and the triangle, with its corners' values blended at the hit as the GL
// blends them. The ray-cast picture shades by it; a view's data passes
// (surface_passes.hpp) read its normals.

#include <array>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

struct Surface {
  int material = 0;
  const Mesh* mesh = nullptr;
  size_t triangle = 0;
};

// The surface of RayHit::object `object` (spheres first, then triangles, then each mesh's triangles).
Surface surface_of(const Scene& scene, int object);

// A mesh triangle's per-corner values at `p`, blended by p's barycentric
// weights as the GL interpolates them across the triangle (perspective-correct).
struct CornerBlend {
  double wa = 1.0, wb = 0.0, wc = 0.0;
  CornerBlend(const Surface& s, const glm::dvec3& p);
  glm::dvec2 operator()(const std::array<glm::vec2, 3>& v) const {
    return wa * glm::dvec2(v[0]) + wb * glm::dvec2(v[1]) + wc * glm::dvec2(v[2]);
  }
  glm::dvec3 operator()(const std::array<glm::vec3, 3>& v) const {
    return wa * glm::dvec3(v[0]) + wb * glm::dvec3(v[1]) + wc * glm::dvec3(v[2]);
  }
};

// The normal a smooth mesh face is shaded with at `p` (its corners' blended,
// of unit length), or none for a flat face, as the triangle shader decides.
std::optional<glm::dvec3> shading_normal(const Surface& s, const glm::dvec3& p);

}  // namespace umbra
