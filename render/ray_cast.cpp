#include "render/ray_cast.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "render/camera_transform.hpp"

namespace umbra {
namespace {

// Both roots of |o + t d - c|^2 = R^2 for unit d, in the stable form.
std::optional<double> hit_sphere(const Sphere& s, const glm::dvec3& o, const glm::dvec3& d) {
  const glm::dvec3 oc = o - s.center;
  const double b = glm::dot(oc, d);
  const glm::dvec3 closest = oc - b * d;
  const double h = s.radius * s.radius - glm::dot(closest, closest);
  if (h < 0.0) return std::nullopt;
  const double root = std::sqrt(h);
  if (-b - root > 0.0) return -b - root;
  if (-b + root > 0.0) return -b + root;
  return std::nullopt;
}

// Moller-Trumbore, accepting either side; the edges are inclusive.
std::optional<double> hit_triangle(const Triangle& tri, const glm::dvec3& o, const glm::dvec3& d) {
  const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return std::nullopt;  // parallel to the plane, or degenerate
  const glm::dvec3 s = o - tri.a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) / det;
  if (t > 0.0) return t;
  return std::nullopt;
}

}  // namespace

std::optional<RayHit> nearest_hit(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction,
                                  int skip) {
  std::optional<RayHit> best;
  const int sphere_count = int(scene.spheres.size());
  for (int i = 0; i < sphere_count; ++i) {
    if (i == skip) continue;
    const auto t = hit_sphere(scene.spheres[size_t(i)], origin, direction);
    if (t && (!best || *t < best->t)) {
      const glm::dvec3 p = origin + *t * direction;
      best = RayHit{*t, p, (p - scene.spheres[size_t(i)].center) / scene.spheres[size_t(i)].radius, i};
    }
  }
  for (size_t j = 0; j < scene.triangles.size(); ++j) {
    const int id = sphere_count + int(j);
    if (id == skip) continue;
    const Triangle& tri = scene.triangles[j];
    const auto t = hit_triangle(tri, origin, direction);
    if (t && (!best || *t < best->t))
      best = RayHit{*t, origin + *t * direction, glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a)), id};
  }
  return best;
}

bool shadow_ray_blocked(const Scene& scene, const glm::dvec3& point, int self, const glm::dvec3& light) {
  // A sphere cannot shadow the lit side of itself, nor a triangle itself, so
  // `self` is skipped rather than nudging the ray's origin by an epsilon.
  const glm::dvec3 to_light = light - point;
  const double distance = glm::length(to_light);
  const auto hit = nearest_hit(scene, point, to_light / distance, self);
  return hit && hit->t < distance;
}

uint8_t reference_mask_value(const Scene& scene, int width, int height, double px, double py, size_t light) {
  const glm::dvec3 eye = scene.camera.eye;
  const auto hit = nearest_hit(scene, eye, pixel_ray_direction(scene.camera, width, height, px, py));
  if (!hit) return kMaskNoSurface;
  glm::dvec3 n = hit->normal;
  if (glm::dot(n, eye - hit->point) < 0.0) n = -n;  // the side facing the camera
  const glm::dvec3 l = scene.lights[light].position;
  if (glm::dot(n, l - hit->point) <= 0.0) return kMaskUnlit;
  return shadow_ray_blocked(scene, hit->point, hit->object, l) ? kMaskUnlit : kMaskLit;
}

}  // namespace umbra
