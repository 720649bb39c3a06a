#pragma once
// The CPU reference: eye rays and exact shadow rays in double precision
// against true spheres, triangles and the triangles of meshes. It answers, per pixel, what the shadow
// mask must be; tests compare the GL renderer's mask with it.

#include <array>
#include <optional>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"
#include "image/image.hpp"

namespace umbra {

struct RayHit {
  double t = 0.0;         // distance along the (unit) ray
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0};  // unit; the outward normal for spheres, either side for triangles
  int object = -1;         // spheres first, then triangles, then each mesh's triangles, in file order
  // A triangle's corners, in its file's order (which sets its normal's
  // side); null for a sphere.
  std::array<const glm::dvec3*, 3> corners{nullptr, nullptr, nullptr};
};

// True when the side of the hit surface that the eye sees faces the light.
// For a triangle this is decided once for the whole triangle, by the exact
// orientation predicate: the eye and the light strictly on one side of its
// plane. A light in the plane lights neither side, however the hit point
// rounds. For a sphere, by the outward normal at the hit.
bool seen_side_faces_light(const RayHit& hit, const glm::dvec3& eye, const glm::dvec3& light);

// The nearest hit with t > t_min, skipping object `skip` (-1: none).
std::optional<RayHit> nearest_hit(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction,
                                  int skip = -1, double t_min = 0.0);
inline std::optional<RayHit> nearest_hit(const Scene& scene, const Ray& ray) { return nearest_hit(scene, ray.origin, ray.direction); }

// Where a shadow ray starts, as a fraction of its length (see shadow_ray_blocked).
constexpr double kShadowRayStart = 1e-9;
// Where the shadow ray from `point` toward a light `distance` away starts:
// kShadowRayStart of its length, as rounding on a shared edge is relative to
// the coordinates; for a light more than kFarLight times further than the
// point's own coordinates are large, kShadowRayStart of that instead (a
// light 1e20 away once started its rays 1e11 out, past every blocker).
constexpr double kFarLight = 1e3;
double shadow_ray_start(const glm::dvec3& point, double distance);

// True when anything lies strictly between `point` (on object `self`) and the
// light, from kShadowRayStart of the way on.
bool shadow_ray_blocked(const Scene& scene, const glm::dvec3& point, int self, const glm::dvec3& light);

// The mask value for the ray through image point (px, py) (pixel centre at
// integer + 0.5 offsets handled by the caller: px = x gives the centre of
// column x) for light `light`, with the same rule as ShadowRenderer::render_mask.
uint8_t reference_mask_value(const Scene& scene, int width, int height, double px, double py, size_t light);

}  // namespace umbra
