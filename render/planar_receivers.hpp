#pragma once
// Planar projected shadows (Blinn 1988) need planar receivers: the
// planes of the scene's triangles, coplanar triangles merged (a floor of two
// triangles is one receiver). Spheres and meshes receive no planar shadow.

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "render/render_plan.hpp"
#include "scene/scene.hpp"

namespace umbra {

struct ReceiverPlane {
  glm::dvec4 plane{0.0};    // (n, d): n . x + d = 0, n unit
  std::vector<int> lines;   // the scene lines of its triangles
  size_t first_triangle = 0;  // index into Scene::triangles, for exact tests
};

// Planes closer than a relative 1e-9 (in normal and offset) are one.
// Degenerate triangles have no plane.
std::vector<ReceiverPlane> receiver_planes(const Scene& scene);

// The matrix that projects a point along the ray from `light` onto `plane`
// (Blinn's projection matrix, for any plane): S x = (p . l) x - (p . x) l.
glm::dmat4 planar_shadow_matrix(const glm::dvec4& plane, const glm::dvec3& light);

// A light's plan for planar projection (--method planar): which of
// `receivers` take its shadow (not those whose plane holds the light), and
// every caster as the triangles projected onto them.
void plan_planar_light(const Scene& scene, const std::vector<ReceiverPlane>& receivers, int segments, const Light& light,
                       LightPlan& lp);

}  // namespace umbra
