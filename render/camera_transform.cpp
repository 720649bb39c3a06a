#include "render/camera_transform.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace umbra {

double near_plane(const Camera& camera) { return kNearPlaneFraction * glm::length(camera.target - camera.eye); }

glm::dmat4 view_matrix(const Camera& camera) { return glm::lookAt(camera.eye, camera.target, camera.up); }

glm::dmat4 infinite_perspective(double fovy_deg, double aspect, double near) {
  const double f = 1.0 / std::tan(glm::radians(fovy_deg) / 2.0);
  glm::dmat4 p(0.0);
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[2][2] = -(1.0 - kInfiniteFarEpsilon);
  p[2][3] = -1.0;
  p[3][2] = -(2.0 - kInfiniteFarEpsilon) * near;
  return p;
}

glm::dvec3 pixel_ray_direction(const Camera& camera, int width, int height, double px, double py) {
  const double t = std::tan(glm::radians(camera.fovy_deg) / 2.0);
  const double x = (2.0 * (px + 0.5) / width - 1.0) * t * double(width) / height;
  const double y = (1.0 - 2.0 * (py + 0.5) / height) * t;
  // The rows of the view matrix's rotation are the camera's axes in world space.
  const glm::dmat4 view = view_matrix(camera);
  const glm::dvec3 right{view[0][0], view[1][0], view[2][0]};
  const glm::dvec3 up{view[0][1], view[1][1], view[2][1]};
  const glm::dvec3 back{view[0][2], view[1][2], view[2][2]};
  return glm::normalize(x * right + y * up - back);
}

}  // namespace umbra
