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

// A perspective camera sees along rays from its eye; an orthographic one
// (ortho_height above 0) along parallel rays, one through each pixel, from
// the plane through its eye square to its view axis, forward: what lies
// behind that plane it does not see.
struct Camera {
  glm::dvec3 eye{0.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fovy_deg = 45.0;     // perspective: the vertical field of view
  double ortho_height = 0.0;  // above 0: orthographic, the height it sees, in scene units (fovy_deg unused)

  bool orthographic() const { return ortho_height > 0.0; }
  // Every member, as declared: a member added joins it (plans are kept while the camera compares equal).
  bool operator==(const Camera&) const = default;

  CameraAxes axes() const;
  // World to the camera's own frame (looking down -z, +y up): OpenGL's convention.
  glm::dmat4 view() const;
  // The camera's frame back to world: a dataset's camera pose (inverse of view()).
  glm::dmat4 pose() const;
  // Perspective: its far plane at infinity, with depth scaled by
  // (1 - kInfiniteFarEpsilon) (Everitt and Kilgard, "Practical and Robust
  // Stenciled Shadow Volumes for Hardware-Accelerated Rendering", 2002):
  // shadow volumes extruded to infinity stay inside it; `far` unused.
  // Orthographic: depth from `near` to `far` along the view axis, which
  // no projection can take to infinity (a point at infinity lies off every
  // orthographic picture but along the axis): its shadow volumes stop at a
  // finite reach (volume_reach.hpp) and are drawn with depth clamping.
  glm::dmat4 projection(double aspect, double near, double far = 0.0) const;
  glm::dmat4 view_projection(double aspect, double near, double far = 0.0) const { return projection(aspect, near, far) * view(); }
  // Perspective: tan(fovy / 2), the picture's half-height at unit depth.
  double half_height_at_unit_depth() const;
  // Perspective: the focal length in pixels of a picture `height` pixels
  // high; orthographic: pixels per scene unit (width and height alike: square pixels).
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

// The pixel rays of one camera and picture size, with the axes and the
// lens's scale worked out once (the ray caster's samples).
class PixelRays {
 public:
  PixelRays(const Camera& camera, int width, int height);
  Ray ray(double px, double py) const;

 private:
  double width_, height_, scale_;  // scale_: tan(fovy / 2), or orthographic, half the height seen
  bool orthographic_;
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
// An orthographic camera's near plane is its eye's (0: it sees from there).
double near_plane(const Camera& camera, double aspect, const SceneBounds& surfaces, double nearest_surface);
// An orthographic camera's far plane: past the far side of the surfaces'
// box by a hundredth of its depth (1 where nothing lies ahead).
double far_plane(const Camera& camera, const SceneBounds& surfaces);

// With the far plane at infinity, a vertex at infinity lands exactly on the
// far plane and rounding may clip it. Scaling depth by (1 - eps) keeps it
// inside; 2^-22 is the value Lengyel derives for a 24-bit depth buffer
// ("Projection Matrix Tricks", GDC 2007).
constexpr double kInfiniteFarEpsilon = 1.0 / (1 << 22);

// A perspective projection as Camera::projection makes it, for any lens (a
// point light's cube-map faces).
glm::dmat4 infinite_perspective(double fovy_deg, double aspect, double near);

// The depth along the view axis of a window depth `window` (0 to 1) that
// `projection` (Camera::projection's) wrote; perspective: infinity at 1.
double view_depth_of_window_depth(const glm::dmat4& projection, double window);

// The rays of a width x height viewport, in GL window coordinates (pixel
// centres at half-integers, row 0 at the bottom): the ray through window
// point (x, y) starts at origins (x, y, 1) and runs along directions (x, y,
// 1) (not unit). Perspective: every origin the centre of projection;
// orthographic: on the near plane, every direction the view axis. A
// fragment shader that traces its pixel's ray from gl_FragCoord by them
// aims within about 1e-7 of the ray's angle; one that interpolates a
// position across a triangle aims only as well as the rasteriser's
// attribute interpolation, which the GL leaves to the implementation.
struct WindowRays {
  glm::dmat3 origins{0.0}, directions{0.0};
};
// For the projection `view_projection`, whose centre of projection is
// `eye` where it is a perspective one.
WindowRays window_rays(const glm::dmat4& view_projection, const glm::dvec3& eye, int width, int height);

}  // namespace umbra
