#pragma once
// Conservative tests, in double precision and without GL, that let a render
// plan do only the work a view calls for: which casters' shadow volumes can
// reach the view at all, and whether the eye's near-plane rectangle lies
// outside every volume (where z-pass is exact and needs no caps).

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

struct BoundingSphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
};

BoundingSphere bounding_sphere(const Sphere& s);
BoundingSphere bounding_sphere(const Triangle& t);
BoundingSphere bounding_sphere(const Mesh& m);

// The corners of the view's near-plane rectangle, in order round it.
struct NearRectangle {
  glm::dvec3 corners[4];
};
NearRectangle near_rectangle(const Camera& camera, double aspect, double near);

// False only when no point of the near rectangle can be in the shadow volume
// that a caster inside `caster` casts from `light`: then no segment from the
// light to the rectangle meets the ball, which is tested against the faces of
// the pyramid they sweep. True when unsure.
bool may_shadow_near_rectangle(const NearRectangle& near, const glm::dvec3& light, const BoundingSphere& caster);

// The same for one triangle, by its plane: false when every corner of the
// rectangle lies on the light's side of the plane, clear of it by more than
// rounding, since the triangle's volume lies wholly on the other side. A
// floor far larger than the view (a staged model's) is then no reason to
// count with z-fail, where its bounding ball alone would say it might be.
bool triangle_may_shadow_near_rectangle(const NearRectangle& near, const glm::dvec3& light, const Triangle& triangle);

// False only when the shadow volume of a caster inside `caster` lies wholly
// outside the view frustum (its far plane at infinity): the ball and every
// ray from the light through it stay outside one of the frustum's planes.
bool volume_may_reach_view(const Camera& camera, const NearRectangle& near, const glm::dvec3& light,
                           const BoundingSphere& caster);

}  // namespace umbra
