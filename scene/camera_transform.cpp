#include "scene/camera_transform.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace umbra {

double near_plane(const Camera& camera, double aspect, const SceneBounds& surfaces, double nearest_surface) {
  if (surfaces.empty()) return kNearPlaneFraction * glm::length(camera.target - camera.eye);
  const glm::dvec3 centre = 0.5 * (surfaces.lo + surfaces.hi);
  const double radius = 0.5 * glm::length(surfaces.hi - surfaces.lo);
  const double farthest = glm::length(centre - camera.eye) + radius;
  double nearest = std::numeric_limits<double>::max();  // view depth of the box's nearest corner
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(k & 1 ? surfaces.hi.x : surfaces.lo.x, k & 2 ? surfaces.hi.y : surfaces.lo.y,
                            k & 4 ? surfaces.hi.z : surfaces.lo.z);
    nearest = std::min(nearest, glm::dot(corner - camera.eye, forward));
  }
  double near = kNearPlaneFraction * farthest;
  if (nearest > 0.0) near = std::min(near, 0.99 * nearest);
  // The corner ray's angle a from the axis: tan^2 a = tan^2(fovy/2) (1 + aspect^2).
  const double t = std::tan(glm::radians(camera.fovy_deg) / 2.0);
  const double cos_corner = 1.0 / std::sqrt(1.0 + t * t * (1.0 + aspect * aspect));
  near = std::min(near, 0.99 * cos_corner * nearest_surface);
  // The depth the least near plane is a fraction of: the scene's, but no
  // more than kDepthsOfInterest times the distance to what the camera looks
  // at, so that a floor millions of units wide does not push the near plane
  // past the model.
  const double depth = std::min(farthest, kDepthsOfInterest * glm::length(camera.target - camera.eye));
  return std::max(near, kLeastNearPlaneFraction * depth);
}

glm::dmat4 view_matrix(const Camera& camera) { return glm::lookAt(camera.eye, camera.target, camera.up); }

glm::dmat4 infinite_perspective(double fovy_deg, double aspect, double near) {
  return glm::tweakedInfinitePerspective(glm::radians(fovy_deg), aspect, near, kInfiniteFarEpsilon);
}

glm::dvec3 pixel_ray_direction(const Camera& camera, int width, int height, double px, double py) {
  return PixelRays(camera, width, height).direction(px, py);
}

PixelRays::PixelRays(const Camera& camera, int width, int height)
    : width_(width), height_(height), scale_(std::tan(glm::radians(camera.fovy_deg) / 2.0)) {
  // The rows of the view matrix's rotation are the camera's axes in world space.
  const glm::dmat4 view = view_matrix(camera);
  right_ = {view[0][0], view[1][0], view[2][0]};
  up_ = {view[0][1], view[1][1], view[2][1]};
  back_ = {view[0][2], view[1][2], view[2][2]};
}

glm::dvec3 PixelRays::direction(double px, double py) const {
  const double x = (2.0 * (px + 0.5) / width_ - 1.0) * scale_ * width_ / height_;
  const double y = (1.0 - 2.0 * (py + 0.5) / height_) * scale_;
  return glm::normalize(x * right_ + y * up_ - back_);
}

glm::dmat3 window_ray_directions(const glm::dmat4& view_projection, const glm::dvec3& eye, int width, int height) {
  // Under a perspective projection every point of a plane of constant NDC
  // depth has the same homogeneous w after unprojecting, so its offset from
  // the eye is affine in (x, y): three points fix it.
  const glm::dmat4 unproject = glm::inverse(view_projection);
  const auto offset = [&](double x, double y) {
    const glm::dvec4 p = unproject * glm::dvec4(2.0 * x / width - 1.0, 2.0 * y / height - 1.0, 0.0, 1.0);
    return glm::dvec3(p) / p.w - eye;
  };
  const glm::dvec3 origin = offset(0.0, 0.0);
  return glm::dmat3(offset(1.0, 0.0) - origin, offset(0.0, 1.0) - origin, origin);
}

}  // namespace umbra
