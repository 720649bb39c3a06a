#pragma once
// The camera: one type that says, once, where it stands, what it sees and
// how a point of the scene reaches a pixel. Everything that needs the view
// asks it: the GL's matrices, the ray caster's rays, culling, depth, the
// staged framing, the check's defect picture, a dataset's camera poses, and
// the tests. Double precision, no GL (after pbrt-v4's CameraBase: Pharr,
// Jakob and Humphreys, "Physically Based Rendering", 4th ed., 2023, 5.1).
//
// Pixel coordinates: (px, py) with the centre of the top-left pixel at
// (0, 0) and rows growing downward, as an image's rows are stored; the
// pixel's square spans px - 0.5 to px + 0.5.

#include <array>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace umbra {

struct SceneBounds;

// A ray of the camera: it starts at `origin` (the eye) and runs along the unit `direction`.
struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
};

// The camera's axes in world space, unit and orthogonal: `right` and `up`
// along the picture's rows and columns, `forward` along its view axis.
struct CameraAxes {
  glm::dvec3 right, up, forward;
};

// Where a point of the scene lands in a picture: its pixel coordinates (as
// above, continuous) and its depth along the view axis (positive ahead).
struct Projected {
  double px = 0.0, py = 0.0, depth = 0.0;
};

struct Camera {
  glm::dvec3 eye{0.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fovy_deg = 45.0;  // the vertical field of view

  bool operator==(const Camera& o) const { return eye == o.eye && target == o.target && up == o.up && fovy_deg == o.fovy_deg; }
  bool operator!=(const Camera& o) const { return !(*this == o); }

  CameraAxes axes() const;
  // World to the camera's own frame (looking down -z, +y up): OpenGL's convention.
  glm::dmat4 view() const;
  // The camera's frame back to world: a dataset's camera pose (inverse of view()).
  glm::dmat4 pose() const;
  // Perspective whose far plane is at infinity, with depth scaled by
  // (1 - kInfiniteFarEpsilon) (Everitt and Kilgard, "Practical and Robust
  // Stenciled Shadow Volumes for Hardware-Accelerated Rendering", 2002):
  // shadow volumes extruded to infinity stay inside it.
  glm::dmat4 projection(double aspect, double near) const;
  glm::dmat4 view_projection(double aspect, double near) const { return projection(aspect, near) * view(); }
  // tan(fovy / 2): the picture's half-height at unit depth.
  double half_height_at_unit_depth() const;
  // The focal length in pixels of a picture `height` pixels high (width and height alike: square pixels).
  double focal_length_pixels(int height) const;
  // The ray through pixel (px, py) of a width x height picture.
  Ray pixel_ray(int width, int height, double px, double py) const;
  // Where `point` lands in a width x height picture; its depth is <= 0 when
  // it is not ahead of the eye (its pixel coordinates then mean nothing).
  Projected project(const glm::dvec3& point, int width, int height) const;
  // The corners of the frustum's cross-section at `depth` ahead of the eye,
  // in a picture `aspect` (width over height) wide: bottom left, bottom
  // right, top right, top left.
  std::array<glm::dvec3, 4> section_corners(double aspect, double depth) const;
};
// A member added to Camera must join operator== (plans are kept while the camera compares equal).
static_assert(sizeof(Camera) == 10 * sizeof(double), "compare the new member of Camera in operator==");

// The pixel rays of one camera and picture size, with the axes and the
// lens's scale worked out once (the ray caster's samples).
class PixelRays {
 public:
  PixelRays(const Camera& camera, int width, int height);
  Ray ray(double px, double py) const;

 private:
  double width_, height_, scale_;  // scale_: tan(fovy / 2)
  glm::dvec3 eye_;
  CameraAxes axes_;
};

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

// With the far plane at infinity, a vertex at infinity lands exactly on the
// far plane and rounding may clip it. Scaling depth by (1 - eps) keeps it
// inside; 2^-22 is the value Lengyel derives for a 24-bit depth buffer
// ("Projection Matrix Tricks", GDC 2007).
constexpr double kInfiniteFarEpsilon = 1.0 / (1 << 22);

// A perspective projection as Camera::projection makes it, for any lens (a
// point light's cube-map faces).
glm::dmat4 infinite_perspective(double fovy_deg, double aspect, double near);

// The depth along the view axis of a window depth `window` (0 to 1) that
// `projection` (Camera::projection's) wrote; infinity at 1.
double view_depth_of_window_depth(const glm::dmat4& projection, double window);

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
