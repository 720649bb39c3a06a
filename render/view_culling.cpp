#include "render/view_culling.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/camera.hpp"

namespace umbra {
namespace {

// n . x + d >= 0 inside; n is unit.
struct Plane {
  glm::dvec3 n{0.0};
  double d = 0.0;
  double distance(const glm::dvec3& p) const { return glm::dot(n, p) + d; }
};

// The plane through a, b, c with `inside` on its positive side; nothing when
// the three points (nearly) lie on a line or `inside` (nearly) on the plane.
bool plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& inside,
                   Plane& plane) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  const double size = std::max({glm::length(b - a), glm::length(c - a), glm::length(inside - a)});
  if (!(length > 1e-12 * size * size)) return false;
  plane.n = n / length;
  plane.d = -glm::dot(plane.n, a);
  if (plane.distance(inside) < 0.0) plane.n = -plane.n, plane.d = -plane.d;
  return std::abs(plane.distance(inside)) > 1e-9 * size;
}

// A relative slack so that rounding never calls a touching ball separate.
double slack(const glm::dvec3& p, const BoundingSphere& ball) {
  return 1e-9 * (ball.radius + glm::length(ball.center) + glm::length(p));
}

}  // namespace

BoundingSphere bounding_sphere(const Sphere& s) { return {s.center, s.radius}; }

BoundingSphere bounding_sphere(const Triangle& t) {
  const glm::dvec3 c = (t.a + t.b + t.c) / 3.0;
  return {c, std::max({glm::length(t.a - c), glm::length(t.b - c), glm::length(t.c - c)})};
}

BoundingSphere bounding_sphere(const Mesh& m) {
  const glm::dvec3 c = 0.5 * (m.bounds_min + m.bounds_max);
  return {c, 0.5 * glm::length(m.bounds_max - m.bounds_min)};
}

NearRectangle near_rectangle(const Camera& camera, double aspect, double n) {
  const std::array<glm::dvec3, 4> c = camera.section_corners(aspect, n);
  return {{c[0], c[1], c[2], c[3]}};
}

bool triangle_may_shadow_near_rectangle(const NearRectangle& near, const glm::dvec3& light, const Triangle& triangle) {
  const glm::dvec3 normal = glm::cross(triangle.b - triangle.a, triangle.c - triangle.a);
  const double length = glm::length(normal);
  if (!(length > 0.0)) return true;
  const glm::dvec3 n = normal / length;
  const double light_side = glm::dot(n, light - triangle.a);
  for (const glm::dvec3& corner : near.corners) {
    const double side = glm::dot(n, corner - triangle.a);
    // Clear of the plane by far more than the rounding of the corners and of n.
    const double clearance = 1e-9 * (glm::length(corner - triangle.a) + glm::length(corner));
    if (!(side * light_side > 0.0) || std::abs(side) <= clearance) return true;
  }
  return false;
}

bool may_shadow_near_rectangle(const NearRectangle& near, const glm::dvec3& light, const BoundingSphere& caster) {
  const glm::dvec3* c = near.corners;
  const glm::dvec3 inside = 0.2 * (light + c[0] + c[1] + c[2] + c[3]);
  Plane faces[5];
  if (!plane_through(c[0], c[1], c[2], inside, faces[4])) return true;  // the light in the rectangle's plane
  for (int i = 0; i < 4; ++i)
    if (!plane_through(light, c[i], c[(i + 1) % 4], inside, faces[i])) return true;
  const double margin = caster.radius + slack(light, caster);
  for (const Plane& f : faces)
    if (f.distance(caster.center) < -margin) return false;
  return true;
}

bool volume_may_reach_view(const Camera& camera, const NearRectangle& near, const glm::dvec3& light,
                           const BoundingSphere& caster) {
  const glm::dvec3* c = near.corners;
  const glm::dvec3 centre = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  // The frustum's sides: through the eye and an edge of the near
  // rectangle, or orthographic, through the edge along the view axis.
  const glm::dvec3 along = camera.axes().forward * glm::length(c[0] - centre);
  const glm::dvec3 inside = camera.orthographic() ? centre + along : camera.eye + 2.0 * (centre - camera.eye);  // beyond the near plane, on the axis
  const double margin = caster.radius + slack(light, caster);
  for (int i = 0; i <= 4; ++i) {
    Plane p;
    const bool made = i == 4                  ? plane_through(c[0], c[1], c[2], inside, p)
                      : camera.orthographic() ? plane_through(c[i], c[(i + 1) % 4], c[i] + along, inside, p)
                                              : plane_through(camera.eye, c[i], c[(i + 1) % 4], inside, p);
    if (!made) continue;
    // Outside when the ball is, and every ray from the light through it
    // heads no further in.
    if (p.distance(caster.center) < -margin && glm::dot(p.n, caster.center - light) + margin <= 0.0) return false;
  }
  return true;
}

}  // namespace umbra
