#include "scene/camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "scene/scene.hpp"

namespace umbra {

double far_plane(const Camera& camera, const SceneBounds& surfaces) {
  if (surfaces.empty()) return 1.0;
  const glm::dvec3 forward = camera.axes().forward;
  double farthest = 0.0;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(k & 1 ? surfaces.hi.x : surfaces.lo.x, k & 2 ? surfaces.hi.y : surfaces.lo.y, k & 4 ? surfaces.hi.z : surfaces.lo.z);
    farthest = std::max(farthest, glm::dot(corner - camera.eye, forward));
  }
  return farthest > 0.0 ? 1.01 * farthest : 1.0;
}

double near_plane(const Camera& camera, double aspect, const SceneBounds& surfaces, double nearest_surface) {
  if (camera.orthographic()) return 0.0;
  if (surfaces.empty()) return kNearPlaneFraction * glm::length(camera.target - camera.eye);
  const glm::dvec3 centre = 0.5 * (surfaces.lo + surfaces.hi);
  const double radius = 0.5 * glm::length(surfaces.hi - surfaces.lo);
  const double farthest = glm::length(centre - camera.eye) + radius;
  double nearest = std::numeric_limits<double>::max();  // view depth of the box's nearest corner
  const glm::dvec3 forward = camera.axes().forward;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(k & 1 ? surfaces.hi.x : surfaces.lo.x, k & 2 ? surfaces.hi.y : surfaces.lo.y,
                            k & 4 ? surfaces.hi.z : surfaces.lo.z);
    nearest = std::min(nearest, glm::dot(corner - camera.eye, forward));
  }
  double near = kNearPlaneFraction * farthest;
  if (nearest > 0.0) near = std::min(near, 0.99 * nearest);
  // The corner ray's angle a from the axis: tan^2 a = tan^2(fovy/2) (1 + aspect^2).
  const double t = camera.half_height_at_unit_depth();
  const double cos_corner = 1.0 / std::sqrt(1.0 + t * t * (1.0 + aspect * aspect));
  near = std::min(near, 0.99 * cos_corner * nearest_surface);
  // The depth the least near plane is a fraction of: the scene's, but no
  // more than kDepthsOfInterest times the distance to what the camera looks
  // at, so that a floor millions of units wide does not push the near plane
  // past the model.
  const double depth = std::min(farthest, kDepthsOfInterest * glm::length(camera.target - camera.eye));
  return std::max(near, kLeastNearPlaneFraction * depth);
}

CameraAxes Camera::axes() const {
  // The rows of the view matrix's rotation are the camera's axes in world space.
  const glm::dmat4 v = view();
  return {{v[0][0], v[1][0], v[2][0]}, {v[0][1], v[1][1], v[2][1]}, -glm::dvec3{v[0][2], v[1][2], v[2][2]}};
}

glm::dmat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::dmat4 Camera::pose() const {
  const CameraAxes a = axes();
  glm::dmat4 pose(1.0);
  pose[0] = glm::dvec4(a.right, 0.0), pose[1] = glm::dvec4(a.up, 0.0), pose[2] = glm::dvec4(-a.forward, 0.0);
  pose[3] = glm::dvec4(eye, 1.0);
  return pose;
}

glm::dmat4 Camera::projection(double aspect, double near, double far) const {
  if (!orthographic()) return infinite_perspective(fovy_deg, aspect, near);
  const double h = ortho_height / 2.0, w = h * aspect;
  return glm::ortho(-w, w, -h, h, near, far);
}

double Camera::half_height_at_unit_depth() const { return std::tan(glm::radians(fovy_deg) / 2.0); }

double Camera::focal_length_pixels(int height) const {
  return orthographic() ? height / ortho_height : height / (2.0 * half_height_at_unit_depth());
}

Ray Camera::pixel_ray(int width, int height, double px, double py) const { return PixelRays(*this, width, height).ray(px, py); }

Projected Camera::project(const glm::dvec3& point, int width, int height) const {
  const CameraAxes a = axes();
  const glm::dvec3 q = point - eye;
  const double depth = glm::dot(q, a.forward), focal = focal_length_pixels(height);
  const double over = orthographic() ? 1.0 : depth;  // a perspective's points shrink with their depth
  return {width / 2.0 + focal * glm::dot(q, a.right) / over - 0.5, height / 2.0 - focal * glm::dot(q, a.up) / over - 0.5, depth};
}

std::array<glm::dvec3, 4> Camera::section_corners(double aspect, double depth) const {
  const CameraAxes a = axes();
  const double half_h = orthographic() ? ortho_height / 2.0 : depth * half_height_at_unit_depth(), half_w = half_h * aspect;
  const glm::dvec3 centre = eye + depth * a.forward;
  return {centre - half_w * a.right - half_h * a.up, centre + half_w * a.right - half_h * a.up,
          centre + half_w * a.right + half_h * a.up, centre - half_w * a.right + half_h * a.up};
}

PixelRays::PixelRays(const Camera& camera, int width, int height)
    : width_(width), height_(height),
      scale_(camera.orthographic() ? camera.ortho_height / 2.0 : camera.half_height_at_unit_depth()),
      orthographic_(camera.orthographic()), eye_(camera.eye), axes_(camera.axes()) {}

Ray PixelRays::ray(double px, double py) const {
  const double x = (2.0 * (px + 0.5) / width_ - 1.0) * scale_ * width_ / height_;
  const double y = (1.0 - 2.0 * (py + 0.5) / height_) * scale_;
  if (orthographic_) return {eye_ + x * axes_.right + y * axes_.up, axes_.forward};
  return {eye_, glm::normalize(x * axes_.right + y * axes_.up + axes_.forward)};
}

glm::dmat4 infinite_perspective(double fovy_deg, double aspect, double near) {
  return glm::tweakedInfinitePerspective(glm::radians(fovy_deg), aspect, near, kInfiniteFarEpsilon);
}

double view_depth_of_window_depth(const glm::dmat4& projection, double window) {
  const double z_ndc = 2.0 * window - 1.0;
  // Orthographic (its w row is (0, 0, 0, 1)): z_ndc = P22 z + P32.
  if (projection[2][3] == 0.0) return -(z_ndc - projection[3][2]) / projection[2][2];
  // Perspective: window depth d is (z_ndc + 1) / 2, and z_ndc = (P22 z +
  // P32) / -z for the eye's z (negative ahead): so -z = P32 / (-z_ndc - P22).
  if (window >= 1.0) return std::numeric_limits<double>::infinity();
  return -projection[3][2] / (-z_ndc - projection[2][2]);
}

WindowRays window_rays(const glm::dmat4& view_projection, const glm::dvec3& eye, int width, int height) {
  // A window point's ray through the near plane (z_ndc -1) and a plane
  // behind it (z_ndc 0). Under a perspective projection every point of a
  // plane of constant NDC depth has the same homogeneous w after
  // unprojecting, and under an orthographic one w is 1: either way the
  // point is affine in (x, y), and three points fix it.
  const glm::dmat4 unproject = glm::inverse(view_projection);
  // The w row: 0 0 0 1 for an orthographic projection (a perspective's is the view axis turned back).
  const bool perspective = view_projection[0][3] != 0.0 || view_projection[1][3] != 0.0 || view_projection[2][3] != 0.0;
  const auto at = [&](double x, double y, double z) {
    const glm::dvec4 p = unproject * glm::dvec4(2.0 * x / width - 1.0, 2.0 * y / height - 1.0, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  const auto affine = [](const auto& of) {
    const glm::dvec3 origin = of(0.0, 0.0);
    return glm::dmat3(of(1.0, 0.0) - origin, of(0.0, 1.0) - origin, origin);
  };
  WindowRays rays;
  if (perspective) {
    rays.origins[2] = eye;
    rays.directions = affine([&](double x, double y) { return at(x, y, 0.0) - eye; });
  } else {
    rays.origins = affine([&](double x, double y) { return at(x, y, -1.0); });
    rays.directions[2] = at(0.0, 0.0, 0.0) - at(0.0, 0.0, -1.0);
  }
  return rays;
}

}  // namespace umbra
