#pragma once
// The camera's matrices and pixel rays, in double precision (no GL here).

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

// The near plane, from the scene's surfaces as the eye sees them, whatever
// the camera's target: at this fraction of the distance from the eye to the
// far side of the surfaces' bounding sphere, so that a scene scaled by 1e6 or
// 1e-6 with its camera keeps the same depth precision (for the default view
// of a scene that fills the cube [-1,1]^3 it is 0.05, as it always was);
// but never beyond the nearest corner of their bounding box in front of the
// eye, nor beyond any surface point in view: a point at distance d from the
// eye, inside a frustum whose corner rays make the angle a with the view
// axis, lies at least d cos(a) in front of the eye. `nearest_surface` is a
// lower bound on the distance from the eye to every surface
// (nearest_surface_distance). The far plane is at infinity.
constexpr double kNearPlaneFraction = 0.05 / (3.4 + 1.7320508075688772);
// An eye on a surface would need a near plane at 0, which no projection has:
// below this fraction of the scene's depth range the near plane goes no
// closer (with 24 depth bits and the far plane at infinity it still resolves
// depths 2^-24 / 2^-20 = 1/16 of the way to the far side of the scene).
constexpr double kLeastNearPlaneFraction = 1.0 / (1 << 20);
// That depth is the scene's, but at most this many times the distance from
// the eye to the target: what lies further (a floor's far edge) needs no
// depth that fine, and would push the near plane past what the camera
// looks at.
constexpr double kDepthsOfInterest = 64.0;
double near_plane(const Camera& camera, double aspect, const SceneBounds& surfaces, double nearest_surface);

// Everitt and Kilgard: with the far plane at infinity, a vertex at infinity
// lands exactly on the far plane and rounding may clip it. Scaling depth by
// (1 - eps) keeps it inside; 2^-22 is the value Lengyel derives for a 24-bit
// depth buffer ("Projection Matrix Tricks", GDC 2007).
constexpr double kInfiniteFarEpsilon = 1.0 / (1 << 22);

glm::dmat4 view_matrix(const Camera& camera);

// Perspective projection whose far plane is at infinity, with depth scaled by
// (1 - eps) (Everitt and Kilgard 2002): GLM's tweakedInfinitePerspective,
// whose third row gives A = -(1 - eps), B = -(2 - eps) near.
glm::dmat4 infinite_perspective(double fovy_deg, double aspect, double near);

// The world-space ray through the centre of pixel (px, py) of a width x height
// image whose row 0 is the top row. Returns the unit direction; it starts at the eye.
glm::dvec3 pixel_ray_direction(const Camera& camera, int width, int height, double px, double py);

// The same for many rays of one view: the camera's axes and the lens's
// scale worked out once (the ray caster's samples).
class PixelRays {
 public:
  PixelRays(const Camera& camera, int width, int height);
  glm::dvec3 direction(double px, double py) const;

 private:
  double width_, height_, scale_;  // scale_: tan(fovy / 2)
  glm::dvec3 right_, up_, back_;
};

// The matrix M for which M (x, y, 1) is the direction (not unit) of the ray
// from `eye` through the point (x, y) of a width x height viewport, in GL
// window coordinates (pixel centres at half-integers, row 0 at the bottom),
// for a perspective `view_projection` whose centre of projection is `eye`.
// A fragment shader that traces its pixel's ray from gl_FragCoord by it
// aims within about 1e-7 of the ray's angle; one that interpolates a
// position across a triangle aims only as well as the rasteriser's
// attribute interpolation, which the GL leaves to the implementation.
glm::dmat3 window_ray_directions(const glm::dmat4& view_projection, const glm::dvec3& eye, int width, int height);

}  // namespace umbra
